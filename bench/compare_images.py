#!/usr/bin/python3
"""Compares two linear renders of one view (rt's and a reference's), for bench/compare_cycles.sh.

    compare_images.py RT.exr REFERENCE.exr --background R,G,B [--noise RT_OTHER_SEED.exr] [--picture OUT.jpg]
    compare_images.py RENDER.exr CONVERGED.exr --background R,G,B --unscaled

Prints one line: scale coverage mre rms model_mre model_rms [the last four for the noise].
scale = mean(reference) / mean(rt), the one factor that matches exposure over the whole image;
rt's image is multiplied by it before the differences are taken. mre: the mean over pixels and
channels of |rt - reference| / (reference + 0.01) (the 0.01 keeps black pixels from dominating);
rms: the root-mean-square difference over the reference's mean. Both over the whole image, then
over the model's pixels only (coverage: their share), those where either image is not exactly the
background colour (a constant background is exact in both renderers). With --noise, the same four
figures between RT.exr and a render of rt's with another seed: what noise alone gives (a floor;
the reference's own noise adds to it). --picture writes rt | reference |
relative error side by side (the first two through the sRGB curve, the third from black at 0 to white
at 50 %).
With --unscaled (a render against a converged render of the same renderer: the equal-time
comparison), no scale is applied and the line is: mre rms model_mre model_rms.
"""

import argparse
import sys

import numpy
import OpenImageIO as oiio

EPSILON = 0.01
ERROR_WHITE = 0.5


def read_rgb(path):
    image = oiio.ImageBuf(path)
    if image.has_error:
        sys.exit(f"compare_images.py ERROR: {path}: {image.geterror()}")
    return image.get_pixels(oiio.FLOAT)[:, :, :3].astype(numpy.float64)


def relative_error(rt, reference):
    return numpy.abs(rt - reference) / (numpy.abs(reference) + EPSILON)


def figures(rt, reference, mask):
    """mre and rms over the whole image, then over the pixels the mask selects."""
    result = []
    for pixels in (numpy.ones_like(mask), mask):
        a, b = rt[pixels], reference[pixels]
        result += [relative_error(a, b).mean(), numpy.sqrt(((a - b) ** 2).mean()) / b.mean()]
    return result


def model_pixels(images, background):
    return numpy.any([numpy.any(image != background, axis=2) for image in images], axis=0)


def to_srgb(linear):
    image = oiio.ImageBuf(oiio.ImageSpec(linear.shape[1], linear.shape[0], 3, oiio.FLOAT))
    image.set_pixels(oiio.ROI(), linear.astype(numpy.float32))
    return oiio.ImageBufAlgo.colorconvert(image, "linear", "sRGB").get_pixels(oiio.FLOAT)


def write_picture(path, rt, reference):
    error = relative_error(rt, reference).mean(axis=2, keepdims=True) / ERROR_WHITE
    strip = numpy.concatenate((to_srgb(rt), to_srgb(reference), numpy.repeat(error, 3, axis=2)), axis=1)
    picture = oiio.ImageBuf(oiio.ImageSpec(strip.shape[1], strip.shape[0], 3, oiio.FLOAT))
    picture.set_pixels(oiio.ROI(), numpy.clip(strip, 0, 1).astype(numpy.float32))
    picture.specmod().attribute("Compression", "jpeg:85")
    if not picture.write(path, oiio.UINT8):
        sys.exit(f"compare_images.py ERROR: {path}: {picture.geterror()}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("rt")
    parser.add_argument("reference")
    parser.add_argument("--background", required=True, help="the constant background's R,G,B")
    parser.add_argument("--noise", help="rt's render with another seed")
    parser.add_argument("--picture", help="side-by-side picture to write")
    parser.add_argument("--unscaled", action="store_true", help="the same renderer's converged render: no scale")
    args = parser.parse_args()
    rt, reference = read_rgb(args.rt), read_rgb(args.reference)
    if rt.shape != reference.shape:
        sys.exit(f"compare_images.py ERROR: {args.rt}: {rt.shape[1]}x{rt.shape[0]}, reference "
                 f"{reference.shape[1]}x{reference.shape[0]}")
    background = numpy.array([float(c) for c in args.background.split(",")])
    mask = model_pixels((rt, reference), background)
    if args.unscaled:
        print(" ".join(f"{value:.4f}" for value in figures(rt, reference, mask)))
        return
    scale = reference.mean() / rt.mean()
    line = [scale, mask.mean(), *figures(rt * scale, reference, mask)]
    if args.noise:
        line += figures(read_rgb(args.noise), rt, mask)
    if args.picture:
        write_picture(args.picture, rt * scale, reference)
    print(" ".join(f"{value:.4f}" for value in line))


if __name__ == "__main__":
    main()
