// rt-convert: glTF, OBJ, 3DS and the rest of Assimp's formats to the thesis XML+RAW scene
// (docs/conversion.md). The importers live in libtrace/import; this file parses options,
// writes and reports.
#include <CLI/CLI.hpp>

#include <iostream>

#include "command_line.h"
#include "core/error.h"
#include "core/text.h"
#include "io/import.h"
#include "io/xml_writer.h"
#include "os/atomic_file.h"
#include "scene/thesis_scenes.h"
#include "summary.h"
#include "tool.h"

namespace {

struct Options {
    std::string input;
    std::string generate;
    std::string output;
    bool json = false;
    bool quiet = false;
    rt::ImportOptions import;
    std::string upAxis;  // empty: the format's convention
};

// --generate: a test scene of the thesis (scenes/thesis/README.md) in place of a model file.
rt::ImportResult generateThesisScene(const std::string& name) {
    rt::ImportResult result{rt::thesisScene(name), {}};
    rt::ImportReport& r = result.report;
    r.format = "thesis Table 4.1 scene";
    r.meshes = result.scene.models.size();
    r.camerasInFile = 1;
    r.cameraUsed = name;
    r.lightsInFile = result.scene.lights.size();
    return result;
}

int convert(Options& o) {
    if (o.input.empty() == o.generate.empty()) throw rt::InputError("give either a model file or --generate NAME");
    if (o.json && o.output == "-")
        throw rt::InputError("--json prints on standard output, where -o - writes the scene");
    if (!o.output.empty() && o.output != "-" && rt::lowerCaseExtension(o.output) != ".xml")
        throw rt::InputError(o.output +
                             ": rt-convert writes rt's XML scene only: name it .xml, or - for standard output");
    if (!o.upAxis.empty()) o.import.upAxis = rt::parseNamed(rt::kUpAxisNames, o.upAxis);
    // An output that cannot be written is bad usage, found before the model is read, as in rt-render.
    if (!o.output.empty()) rt::prepareOutputFile(o.output);
    rt::ImportResult result = o.generate.empty() ? rt::importScene(o.input, o.import) : generateThesisScene(o.generate);
    for (std::string& note : rt::unreadableTextureNotes(result.scene)) result.report.notes.push_back(std::move(note));
    if (!o.output.empty()) rt::saveSceneXml(result.scene, o.output);  // all or nothing (os/atomic_file.h)
    const rt::tool::convert::Summary summary{o.generate.empty() ? o.input : o.generate, o.output, &result};
    if (!o.quiet) rt::tool::convert::printSummary(std::cerr, summary);
    if (o.json) rt::tool::convert::printSummaryJson(std::cout, summary);
    return rt::tool::kExitOk;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{
        "Converts a 3-D model (glTF, OBJ, 3DS and what else Assimp reads) to the rt XML+RAW scene format.\n"
        "Without -o nothing is written: the file is checked and summarised.\n"
        "Examples:\n"
        "  rt-convert model.glb                           check and summarise, write nothing\n"
        "  rt-convert model.obj -o model.xml              the scene, its RAW models in model/\n"
        "  rt-convert room.3ds --up-axis z --camera auto -o room.xml\n"
        "  rt-convert --generate ships -o ships.xml       a test scene of the thesis\n"
        "  cat model.glb | rt-convert - --json -q         the summary as JSON\n"};
    app.set_version_flag("-v,--version", rt::tool::versionLine("rt-convert"));
    Options o;
    app.add_option("input", o.input,
                   "Model file: .gltf, .glb, .obj, .3ds, .ply, .stl, .fbx, .dae, .raw, ...; - reads a glTF 2.0 model "
                   "(GLB or JSON) from standard input");
    app.add_option(
        "--generate", o.generate,
        "Instead of a model file, a test scene of the thesis: " + CLI::detail::join(rt::thesisSceneNames(), ", "));
    app.add_option("-o,--output", o.output,
                   "Scene file to write, .xml (RAW models go in a folder named after it), or - for standard "
                   "output with the geometry inline");
    app.add_option("--scene", o.import.scene, "glTF scene index (default: the file's default scene)")
        ->check(rt::tool::numberIn(0, 1 << 30));
    app.add_option("--camera", o.import.camera,
                   "Camera to use, by name or index (default: the first); auto: ignore the file's cameras and "
                   "frame the scene");
    app.add_option("--scale", o.import.scale, "Uniform scale applied at the root, e.g. 0.01 for centimetres")
        ->check(rt::tool::positiveNumber());
    app.add_option("--up-axis", o.upAxis,
                   "The file's up axis as its author knows it (3DS, FBX, CAD: usually z); the model is turned to "
                   "stand in rt's Y-up world (default: the format's convention, docs/conversion.md)")
        ->check(CLI::IsMember(rt::namesOf(rt::kUpAxisNames)));
    app.add_option("--aspect", o.import.aspect,
                   "Width/height assumed when a camera gives a vertical fov without an aspect ratio")
        ->check(rt::tool::positiveNumber());
    app.add_flag("--flat", o.import.flat, rt::tool::kFlatHelp);
    app.add_flag("--double-sided", o.import.doubleSided, rt::tool::kDoubleSidedHelp);
    app.add_flag("--allow-outside-files", o.import.filesOutsideModelFolder,
                 "Read glTF buffers outside the model's folder (../, absolute paths): only for files you trust");
    rt::tool::addMaxInputOption(app);
    rt::tool::addSandboxOption(app);
    app.add_flag("--json", o.json, "Print the summary as JSON on standard output");
    app.add_flag("-q,--quiet", o.quiet, "Quiet: no summary or notes on standard error (errors still are)");
    if (const std::optional<int> exitCode = rt::tool::parseCommandLine(app, "rt-convert", argc, argv)) return *exitCode;
    return rt::tool::run("rt-convert", [&] { return convert(o); });
}
