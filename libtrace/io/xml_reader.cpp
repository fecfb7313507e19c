#include "io/xml_reader.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <sstream>

#include "core/error.h"

namespace rt {
namespace {

bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

std::string_view trim(std::string_view s) {
    while (!s.empty() && isSpace(s.front())) s.remove_prefix(1);
    while (!s.empty() && isSpace(s.back())) s.remove_suffix(1);
    return s;
}

bool isListed(std::string_view name, std::initializer_list<std::string_view> list) {
    return std::find(list.begin(), list.end(), name) != list.end();
}

}  // namespace

XmlFile::XmlFile(std::string text, std::string name, const SceneParameters& parameters)
    : text_(std::move(text)), name_(std::move(name)) {
    newlinesBefore_.push_back(0);
    for (std::size_t block = 0; block < text_.size(); block += kLineBlock) {
        const auto begin = text_.begin() + std::ptrdiff_t(block);
        const auto end = text_.begin() + std::ptrdiff_t(std::min(block + kLineBlock, text_.size()));
        newlinesBefore_.push_back(newlinesBefore_.back() + std::uint64_t(std::count(begin, end, '\n')));
    }
    // A copy, not in place: pugixml rewrites the text it parses in place (newlines in attributes
    // become spaces), and lineAt counts the newlines of the text as read. UTF-8 only, so that
    // pugixml's offsets are offsets into that text. pugixml never reads a DTD or expands an
    // entity other than the five of XML; the DOCTYPE is kept only to be refused, so that a scene
    // that relies on one hears so instead of losing its entities silently.
    const pugi::xml_parse_result result =
        doc_.load_buffer(text_.data(), text_.size(), pugi::parse_default | pugi::parse_doctype, pugi::encoding_utf8);
    if (!result)
        throw inputErrorAt(name_, lineAt(result.offset), std::string("malformed XML: ") + result.description());
    for (const pugi::xml_node& n : doc_.children())
        if (n.type() == pugi::node_doctype) failAt(n, "DOCTYPE is not allowed: scenes have no DTD and no entities");
    substitute(parameters);
}

// Every attribute value holding a '$', found by XPath: no recursion, however deep the nesting.
void XmlFile::substitute(const SceneParameters& parameters) {
    for (const pugi::xpath_node& found : doc_.select_nodes("//@*[contains(., '$')]")) {
        pugi::xml_attribute a = found.attribute();
        std::string missing;
        const std::optional<std::string> value = substituteParameters(a.value(), parameters, missing);
        if (!value)
            failAt(found.parent(), "attribute '" + std::string(a.name()) + "': parameter $" + missing +
                                       " has no value (give --set " + missing + "=VALUE, or write ${" + missing +
                                       ":-default})");
        a.set_value(value->c_str());
    }
}

int XmlFile::lineAt(std::ptrdiff_t offset) const {
    const std::size_t at = std::min(std::size_t(std::max<std::ptrdiff_t>(offset, 0)), text_.size());
    const std::size_t block = at / kLineBlock;
    const auto from = text_.begin() + std::ptrdiff_t(block * kLineBlock);
    return int(1 + newlinesBefore_[block] + std::uint64_t(std::count(from, text_.begin() + std::ptrdiff_t(at), '\n')));
}

void XmlFile::failAt(pugi::xml_node node, const std::string& message) const {
    std::ptrdiff_t offset = node.offset_debug();
    if (node.type() == pugi::node_pcdata) {  // point at the text itself, not the line break before it
        const std::size_t start = std::string_view(node.value()).find_first_not_of(" \t\r\n");
        if (start != std::string_view::npos) offset += std::ptrdiff_t(start);
    }
    throw inputErrorAt(name_, lineAt(offset), message);
}

XmlElement::XmlElement(const XmlFile& file, pugi::xml_node node, std::initializer_list<std::string_view> allowed)
    : file_(&file), node_(node) {
    for (const pugi::xml_attribute& a : node_.attributes())
        if (!isListed(a.name(), allowed)) fail("unknown attribute '" + std::string(a.name()) + "' on " + tag());
}

std::string XmlElement::tag() const {
    std::string t = "<";
    t += node_.name();
    t += '>';
    return t;
}

void XmlElement::fail(const std::string& message) const { file_->failAt(node_, message); }

std::string XmlElement::string(const char* attribute) const {
    std::optional<std::string> s = optionalString(attribute);
    if (!s) fail(tag() + " needs attribute '" + attribute + "'");
    return *s;
}

std::optional<std::string> XmlElement::optionalString(const char* attribute) const {
    const pugi::xml_attribute a = node_.attribute(attribute);
    if (!a) return std::nullopt;
    return std::string(a.value());
}

bool XmlElement::boolean(const char* attribute, bool fallback) const {
    const std::optional<std::string> text = optionalString(attribute);
    if (!text) return fallback;
    if (*text != "true" && *text != "false") fail(tag() + " " + attribute + " must be true or false");
    return *text == "true";
}

Real XmlElement::parseNumber(const char* attribute, std::string_view text) const {
    std::string_view s = trim(text);
    if (s.size() > 1 && s.front() == '+') s.remove_prefix(1);  // from_chars takes no '+'
    Real value = 0;
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
    const std::string where = tag() + " attribute '" + attribute + "': '" + std::string(text) + "'";
    if (s.empty() || ec == std::errc::invalid_argument || end != s.data() + s.size()) fail(where + " is not a number");
    if (ec == std::errc::result_out_of_range) {
        // Too small is fine (it rounds to zero); too large is not finite.
        long double wide = HUGE_VALL;  // stays if even long double is out of range
        std::from_chars(s.data(), s.data() + s.size(), wide);
        if (std::abs(wide) < 1) return Real(wide);
        fail(where + " is not a finite number");
    }
    if (!std::isfinite(value)) fail(where + " is not a finite number");
    return value;
}

Real XmlElement::number(const char* attribute) const {
    if (!has(attribute)) fail(tag() + " needs attribute '" + attribute + "'");
    return parseNumber(attribute, node_.attribute(attribute).value());
}

Real XmlElement::number(const char* attribute, Real fallback) const {
    return has(attribute) ? number(attribute) : fallback;
}

Real XmlElement::nonNegative(const char* attribute, Real fallback) const {
    const Real v = number(attribute, fallback);
    if (v < 0) fail(tag() + " attribute '" + attribute + "' must not be negative");
    return v;
}

float XmlElement::nonNegativeFloat(const char* attribute, float fallback) const {
    const Real v = nonNegative(attribute, fallback);
    if (v > kMaxColorValue) fail(tag() + " attribute '" + attribute + "' is too large (at most 1e15)");
    return float(v);
}

float XmlElement::floatWithin(const char* attribute, float fallback, double limit) const {
    const Real v = number(attribute, fallback);
    if (std::abs(double(v)) > limit) {
        std::ostringstream range;
        range << "-" << limit << " to " << limit;
        fail(tag() + " attribute '" + attribute + "' is out of range (" + range.str() + ")");
    }
    return float(v);
}

Real XmlElement::positive(const char* attribute) const {
    const Real v = number(attribute);
    if (!(v > 0)) fail(tag() + " attribute '" + attribute + "' must be positive");
    return v;
}

std::vector<Real> XmlElement::numbers(const char* attribute, std::size_t count) const {
    if (!has(attribute)) fail(tag() + " needs attribute '" + attribute + "'");
    std::vector<Real> values;
    std::string_view rest = trim(node_.attribute(attribute).value());
    while (!rest.empty() && values.size() <= count) {
        const std::size_t end = std::size_t(std::find_if(rest.begin(), rest.end(), isSpace) - rest.begin());
        values.push_back(parseNumber(attribute, rest.substr(0, end)));
        rest = trim(rest.substr(end));
    }
    if (values.size() != count)
        fail(tag() + " attribute '" + attribute + "' needs exactly " + std::to_string(count) + " numbers");
    return values;
}

Vec3 XmlElement::xyz(Real fallback) const {
    return {number("x", fallback), number("y", fallback), number("z", fallback)};
}

Color XmlElement::rgb(float fallback) const {
    return {nonNegativeFloat("r", fallback), nonNegativeFloat("g", fallback), nonNegativeFloat("b", fallback)};
}

Color XmlElement::color(const char* attribute, Color fallback) const {
    if (!has(attribute)) return fallback;
    const std::vector<Real> v = numbers(attribute, 3);
    if (v[0] < 0 || v[1] < 0 || v[2] < 0) fail(std::string(attribute) + " must not be negative");
    for (const Real x : v)
        if (x > kMaxColorValue) fail(std::string(attribute) + " is too large (at most 1e15)");
    return {float(v[0]), float(v[1]), float(v[2])};
}

void XmlElement::requireOnlyChildren(std::initializer_list<std::string_view> allowed) const {
    for (const pugi::xml_node& child : node_.children()) {
        if (child.type() != pugi::node_element) file_->failAt(child, "unexpected text in " + tag());
        if (!isListed(child.name(), allowed))
            file_->failAt(child, "unknown element <" + std::string(child.name()) + "> in " + tag());
    }
}

}  // namespace rt
