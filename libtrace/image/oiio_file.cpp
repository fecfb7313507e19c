#include "image/oiio_file.h"

#include <OpenImageIO/filesystem.h>

#include <stdexcept>

#include "os/atomic_file.h"

namespace rt {

void writeImageFile(const std::string& path, const char* oiioFormat, const OIIO::ImageSpec& spec,
                    OIIO::TypeDesc pixelType, const void* pixels) {
    const std::string name = path == "-" ? "standard output" : path;
    auto out = OIIO::ImageOutput::create(oiioFormat);
    if (!out) throw std::runtime_error(name + ": " + OIIO::geterror());
    OIIO::Filesystem::IOVecOutput memory;
    if (!(out->supports("ioproxy") && out->set_ioproxy(&memory)))
        throw std::runtime_error(name + ": OpenImageIO cannot write " + out->format_name() + " files through memory");
    if (!out->open(name, spec) || !out->write_image(pixelType, pixels) || !out->close())
        throw std::runtime_error(name + ": cannot write: " + out->geterror());
    writeFileAtomically(path, [&](std::ostream& os) {
        os.write(reinterpret_cast<const char*>(memory.buffer().data()), std::streamsize(memory.buffer().size()));
    });
}

}  // namespace rt
