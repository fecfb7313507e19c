// rt's MIP map lookups (libtrace/image/mip_map.*) on an 8-bit picture as the shared models store
// theirs (a 2048 x 2048 RGBA noise picture, level 0 in tiles), read the ways the renderers read
// them: a bilinear probe of level 0 (the path tracer's rays after the camera carry no footprint),
// trilinear and anisotropic lookups over a footprint, and the cut-outs' alpha alone. Each
// iteration is kLookups lookups at random points. Time is rough on a loaded machine; count
// instructions per lookup instead (docs/benchmarks.md, "Textures"):
//   valgrind --tool=callgrind --callgrind-out-file=mip.cg build/release/bench/bench_mip_map
//   callgrind_annotate --inclusive=yes --tree=caller mip.cg | grep -B1 '\* .*rt::MipMap::'
// (each benchmark's line: the inclusive instructions of its calls of rt::MipMap::lookup or
// rt::MipMap::bilinear, and how many calls).
#include <benchmark/benchmark.h>

#include <cstdint>
#include <random>
#include <vector>

#include "image/mip_map.h"

namespace {

constexpr int kSide = 2048;
constexpr int kLookups = 1024;

const rt::MipMap& picture() {
    static const rt::MipMap map = [] {
        std::mt19937 random(1);
        std::vector<std::uint8_t> texels(std::size_t(kSide) * kSide * 4);
        for (std::uint8_t& v : texels) v = std::uint8_t(random() & 0xff);
        return rt::MipMap(kSide, kSide, 4, std::move(texels));
    }();
    return map;
}

// kLookups points over the picture and beyond (repeated), with footprints `texels` level-0 texels
// long along s and a quarter of that along t (none for zero).
std::vector<rt::TexCoord> points(float texels) {
    std::mt19937 random(2);
    std::uniform_real_distribution<float> uniform(-0.5f, 1.5f);
    std::vector<rt::TexCoord> at;
    const float d = texels / kSide;
    for (int i = 0; i < kLookups; ++i) at.push_back({uniform(random), uniform(random), d, 0, 0, d / 4});
    return at;
}

// RGB decoded as sRGB colour, as TextureFiles::lookup reads a base colour.
void lookups(benchmark::State& state, rt::TextureFilter filter, float texels) {
    const rt::MipMap& map = picture();
    const std::vector<rt::TexCoord> at = points(texels);
    rt::MipLookup how{.filter = filter, .channels = 3};
    how.decoding.table = rt::srgbByteTable();
    float rgb[3];
    for (auto _ : state)
        for (const rt::TexCoord& c : at) {
            map.lookup(c, how, rgb);
            benchmark::DoNotOptimize(rgb);
        }
    state.SetItemsProcessed(state.iterations() * kLookups);
}

void BM_BilinearNoFootprint(benchmark::State& state) { lookups(state, rt::TextureFilter::Anisotropic, 0); }
void BM_Trilinear(benchmark::State& state) { lookups(state, rt::TextureFilter::Trilinear, 6); }
void BM_Anisotropic(benchmark::State& state) { lookups(state, rt::TextureFilter::Anisotropic, 12); }

// A cut-out's alpha, channel 3, as TextureFiles::alpha reads it during traversal.
void BM_Alpha(benchmark::State& state) {
    const rt::MipMap& map = picture();
    const std::vector<rt::TexCoord> at = points(0);
    rt::MipLookup how{.firstChannel = 3, .channels = 1};
    how.decoding.table = rt::linearByteTable();
    for (auto _ : state)
        for (const rt::TexCoord& c : at) benchmark::DoNotOptimize(map.bilinear(c.s, c.t, how));
    state.SetItemsProcessed(state.iterations() * kLookups);
}

BENCHMARK(BM_BilinearNoFootprint);
BENCHMARK(BM_Trilinear);
BENCHMARK(BM_Anisotropic);
BENCHMARK(BM_Alpha);

}  // namespace
