// The JSON writer and the documents built with it: the report and the tree dump, each
// parsed back by a strict little reader so that the tests catch malformed output, not just
// missing text. The tools' documents are checked against docs/schema by tests/cli/json_schema.sh.
#include <cctype>
#include <map>
#include <memory>
#include <sstream>
#include <variant>

#include "accel/kdtree.h"
#include "accel/naive.h"
#include "core/json_writer.h"
#include "inspect/tree_dump.h"
#include "inspect/tree_report.h"
#include "inspect_fixed_tree.h"
#include "inspect_test_scenes.h"
#include "test_util.h"

using namespace rt;

namespace {

struct Json;
using JsonObject = std::map<std::string, Json>;
using JsonArray = std::vector<Json>;
struct Json {
    std::variant<std::nullptr_t, bool, double, std::string, JsonArray, JsonObject> v;

    const Json& operator[](const std::string& k) const {
        const auto& o = std::get<JsonObject>(v);
        const auto it = o.find(k);
        if (it == o.end()) throw std::runtime_error("no member " + k);
        return it->second;
    }
    const Json& operator[](std::size_t i) const { return std::get<JsonArray>(v).at(i); }
    double num() const { return std::get<double>(v); }
    const std::string& str() const { return std::get<std::string>(v); }
    std::size_t size() const { return std::get<JsonArray>(v).size(); }
    bool has(const std::string& k) const { return std::get<JsonObject>(v).count(k) > 0; }
};

// RFC 8259, without \u escapes beyond control characters; throws on anything malformed.
class JsonReader {
public:
    explicit JsonReader(std::string text) : s_(std::move(text)) {}

    Json document() {
        Json j = value();
        skipSpace();
        if (i_ != s_.size()) fail("text after the document");
        return j;
    }

private:
    [[noreturn]] void fail(const std::string& what) const {
        throw std::runtime_error("JSON at byte " + std::to_string(i_) + ": " + what);
    }
    void skipSpace() {
        while (i_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[i_]))) ++i_;
    }
    char peek() {
        skipSpace();
        if (i_ >= s_.size()) fail("unexpected end");
        return s_[i_];
    }
    void expect(char c) {
        if (peek() != c) fail(std::string("expected ") + c);
        ++i_;
    }
    bool literal(const char* word) {
        const std::string w(word);
        if (s_.compare(i_, w.size(), w) != 0) return false;
        i_ += w.size();
        return true;
    }
    Json value() {
        const char c = peek();
        if (c == '{') return object();
        if (c == '[') return array();
        if (c == '"') return {string()};
        if (literal("true")) return {true};
        if (literal("false")) return {false};
        if (literal("null")) return {nullptr};
        std::size_t used = 0;
        const double d = std::stod(s_.substr(i_, 40), &used);
        if (used == 0) fail("not a value");
        i_ += used;
        return {d};
    }
    std::string string() {
        expect('"');
        std::string out;
        while (i_ < s_.size() && s_[i_] != '"') {
            char c = s_[i_++];
            if (static_cast<unsigned char>(c) < 0x20) fail("raw control character in a string");
            if (c == '\\') {
                const char e = s_.at(i_++);
                const std::map<char, char> simple{{'"', '"'},  {'\\', '\\'}, {'/', '/'},  {'n', '\n'},
                                                  {'r', '\r'}, {'t', '\t'},  {'b', '\b'}, {'f', '\f'}};
                if (e == 'u') {
                    c = char(std::stoi(s_.substr(i_, 4), nullptr, 16));
                    i_ += 4;
                } else if (simple.count(e)) {
                    c = simple.at(e);
                } else {
                    fail("bad escape");
                }
            }
            out += c;
        }
        expect('"');
        return out;
    }
    Json array() {
        expect('[');
        JsonArray a;
        if (peek() == ']') return ++i_, Json{a};
        for (;;) {
            a.push_back(value());
            if (peek() == ']') return ++i_, Json{a};
            expect(',');
        }
    }
    Json object() {
        expect('{');
        JsonObject o;
        if (peek() == '}') return ++i_, Json{o};
        for (;;) {
            if (peek() != '"') fail("expected a key");
            std::string k = string();
            expect(':');
            if (!o.emplace(k, value()).second) fail("duplicate key " + k);
            if (peek() == '}') return ++i_, Json{o};
            expect(',');
        }
    }

    std::string s_;
    std::size_t i_ = 0;
};

Json parse(const std::string& text) { return JsonReader(text).document(); }

Scene oneSphereScene() {
    Scene scene = sceneLookingDownZ();
    scene.looseObjects.add<Sphere>({{0, 0, 5}, 1}, 0);
    scene.lights.push_back({{0, 0, 0}});
    scene.flatten();
    return scene;
}

}  // namespace

TEST(JsonWriter, EscapesAndNestsCorrectly) {
    std::ostringstream out;
    JsonWriter json(out);
    json.beginObject();
    json.member("text", "quote \" backslash \\ newline \n tab \t bell \x07");
    json.member("nan", std::nan(""));
    json.member("third", 1.0 / 3.0);
    json.member("big", std::uint64_t(1) << 60);
    json.member("negative", -7);
    json.key("empty");
    json.beginArray();
    json.endArray();
    json.key("nested");
    json.beginArray();
    json.beginObject();
    json.endObject();
    json.value(true);
    json.null();
    json.endArray();
    json.endObject();
    const Json j = parse(out.str());
    EXPECT_EQ(j["text"].str(), "quote \" backslash \\ newline \n tab \t bell \x07");
    EXPECT_TRUE(std::holds_alternative<std::nullptr_t>(j["nan"].v));
    EXPECT_EQ(j["third"].num(), 1.0 / 3.0);  // exact round trip
    EXPECT_EQ(j["big"].num(), double(std::uint64_t(1) << 60));
    EXPECT_EQ(j["negative"].num(), -7);
    EXPECT_EQ(j["empty"].size(), 0u);
    EXPECT_EQ(j["nested"].size(), 3u);
}

TEST(JsonWriter, RejectsMisuse) {
    std::ostringstream out;
    JsonWriter json(out);
    json.beginObject();
    EXPECT_THROW(json.value(1), std::logic_error);  // a value without a key
    EXPECT_THROW(json.endArray(), std::logic_error);
    EXPECT_THROW(json.beginDocument(), std::logic_error);  // a document is never nested
}

TEST(JsonWriter, DocumentOpensWithItsVersion) {
    std::ostringstream out;
    JsonWriter json(out);
    json.beginDocument();
    json.endObject();
    EXPECT_EQ(out.str(), "{\n  \"version\": " + std::to_string(kJsonSchemaVersion) + "\n}\n");
}

TEST(ReportJson, OneSphereWithTheNaiveList) {
    const Scene scene = oneSphereScene();
    const NaiveAccelerator naive(scene.primitives);
    RenderSettings rays;
    rays.width = 16;
    rays.height = 12;
    rays.shadows = true;
    TreeReport report;
    report.settings.kind = AccelKind::Naive;
    report.stats = naive.stats();
    report.scenePrimitives = scene.primitives.size();
    report.rays = traceRayStatistics(scene, naive, rays);
    report.depths = depthHistogram(naive);

    std::ostringstream out;
    writeReportJson(out, {"one \"sphere\".xml", {{"triangles", 0}, {"spheres", 1}}, 1, {}}, rays, {report});
    const Json j = parse(out.str());
    EXPECT_EQ(j["version"].num(), kJsonSchemaVersion);
    EXPECT_EQ(j["scene"]["file"].str(), "one \"sphere\".xml");
    EXPECT_EQ(j["scene"]["spheres"].num(), 1);
    EXPECT_EQ(j["picture"]["width"].num(), 16);
    EXPECT_EQ(j["picture"]["region"][2].num(), 16);  // the whole picture, x1 exclusive
    EXPECT_EQ(j["picture"]["reflectionDepth"].num(), 5);
    ASSERT_EQ(j["trees"].size(), 1u);
    const Json& t = j["trees"][0];
    EXPECT_EQ(t["name"].str(), "naive");
    EXPECT_EQ(t["nodes"].num(), 1);
    EXPECT_EQ(t["leaves"].num(), 1);
    EXPECT_EQ(t["emptyLeaves"].num(), 0);
    EXPECT_EQ(t["primitiveReferences"].num(), 1);
    EXPECT_EQ(t["rays"]["cameraRays"].num(), 16 * 12);
    // Light at the camera: every visible point faces it, so one shadow ray per camera hit.
    EXPECT_GT(t["rays"]["shadowRays"].num(), 0);
    EXPECT_LT(t["rays"]["shadowRays"].num(), 16 * 12);
    EXPECT_EQ(t["rays"]["intersectionTestsPerRay"].num(), 1);  // one primitive, one test per ray
    ASSERT_EQ(t["depthHistogram"].size(), 1u);
    EXPECT_EQ(t["depthHistogram"][0]["primitiveReferences"].num(), 1);
}

TEST(ReportJson, SettingsOfEachKind) {
    TreeReport bsp, kd;
    bsp.settings.kind = AccelKind::Bsp;
    bsp.settings.bsp.maxDepth = 7;
    bsp.stats.name = "bsp";
    kd.settings.kind = AccelKind::Kd;
    kd.settings.kd.splitMethod = KdSplitMethod::Sample;
    kd.stats.name = "kd";
    std::ostringstream out;
    writeReportJson(out, {}, std::nullopt, {bsp, kd});
    const Json j = parse(out.str());
    EXPECT_FALSE(j.has("picture"));
    EXPECT_EQ(j["trees"][0]["settings"]["maxDepth"].num(), 7);
    EXPECT_EQ(j["trees"][1]["settings"]["split"].str(), "sample");
    EXPECT_FALSE(j["trees"][1].has("rays"));
}

// The KD depth limit is a number even when the tree chose it (8 + 1.3 log2 N), with a
// flag saying so; it once was the string "auto".
TEST(ReportJson, KdDepthLimitIsTheNumberTheTreeUsed) {
    TreeReport chosen, given;
    chosen.settings.kind = given.settings.kind = AccelKind::Kd;
    chosen.scenePrimitives = given.scenePrimitives = 1024;
    given.settings.kd.maxDepth = 12;
    std::ostringstream out;
    writeReportJson(out, {}, std::nullopt, {chosen, given});
    const Json j = parse(out.str());
    EXPECT_EQ(j["trees"][0]["settings"]["maxDepth"].num(), defaultKdMaxDepth(1024));
    EXPECT_TRUE(std::get<bool>(j["trees"][0]["settings"]["maxDepthAuto"].v));
    EXPECT_EQ(j["trees"][1]["settings"]["maxDepth"].num(), 12);
    EXPECT_FALSE(std::get<bool>(j["trees"][1]["settings"]["maxDepthAuto"].v));
}

TEST(TreeJson, NestedLikeTheTree) {
    std::ostringstream out;
    writeTreeJson(out, FixedTree::sample(), {});
    const Json j = parse(out.str());
    EXPECT_EQ(j["version"].num(), kJsonSchemaVersion);
    EXPECT_EQ(j["structure"].str(), "fixed");
    const Json& root = j["root"];
    EXPECT_EQ(root["axis"].str(), "x");
    ASSERT_EQ(root["children"].size(), 2u);
    EXPECT_EQ(root["children"][0]["primitives"].num(), 2);
    const Json& right = root["children"][1];
    EXPECT_EQ(right["id"].num(), 2);
    EXPECT_EQ(right["split"].num(), 1);
    ASSERT_EQ(right["children"].size(), 2u);
    EXPECT_EQ(right["children"][1]["primitives"].num(), 3);
    EXPECT_EQ(right["children"][1]["bounds"]["lo"][1].num(), 1);
}

TEST(TreeJson, CutAtDepth) {
    TreeCut cut;
    cut.maxDepth = 1;
    std::ostringstream out;
    writeTreeJson(out, FixedTree::sample(), cut);
    const Json j = parse(out.str());
    EXPECT_EQ(j["cutDepth"].num(), 1);
    const Json& right = j["root"]["children"][1];
    EXPECT_FALSE(right.has("children"));
    EXPECT_TRUE(std::get<bool>(right["cutOff"].v));
}
