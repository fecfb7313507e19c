#include "light_option.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "core/error.h"
#include "core/text.h"

namespace rt::tool::render {

namespace {

template <std::size_t N>
std::optional<std::vector<double>> numbers(std::string_view text) {
    const auto values = parseSeparated<double, N>(text, ",");
    if (!values) return std::nullopt;
    return std::vector<double>(values->begin(), values->end());
}

// The numbers after the type: as many as one of the forms takes (3, 6, 7, 10 or 11).
std::optional<std::vector<double>> lightNumbers(std::string_view text) {
    switch (std::count(text.begin(), text.end(), ',') + 1) {
        case 3:
            return numbers<3>(text);
        case 6:
            return numbers<6>(text);
        case 7:
            return numbers<7>(text);
        case 10:
            return numbers<10>(text);
        case 11:
            return numbers<11>(text);
        default:
            return std::nullopt;
    }
}

// What each type takes: its numbers before the colour, and the forms it has.
struct LightForm {
    std::size_t geometry;      // position, direction or target
    std::size_t optionalCone;  // 1: a cone may follow
    const char* grammar;
};

LightForm formOf(Light::Type type) {
    if (type == Light::Type::Spot) return {6, 1, "spot:X,Y,Z,TX,TY,TZ[,CONE[,R,G,B[,W]]]"};
    if (type == Light::Type::Directional) return {3, 0, "sun:DX,DY,DZ[,R,G,B[,W]]"};
    return {3, 0, "point:X,Y,Z[,R,G,B[,W]]"};
}

std::string typeNames() {
    std::string names;
    for (const std::string& name : namesOf(kLightOptionNames)) names += (names.empty() ? "" : ", ") + name;
    return names;
}

Vec3 vectorAt(const std::vector<double>& v, std::size_t i) { return {Real(v[i]), Real(v[i + 1]), Real(v[i + 2])}; }

// The colour R,G,B times W from `v[first]` on, white where the value stops before it.
Color colorFrom(const std::vector<double>& v, std::size_t first, const std::string& what) {
    if (v.size() <= first) return {1, 1, 1};
    const double w = v.size() > first + 3 ? v[first + 3] : 1;
    if (!(v[first] >= 0 && v[first + 1] >= 0 && v[first + 2] >= 0 && w >= 0))
        throw InputError(what + ": the colour R,G,B and its weight W must not be negative");
    return Color{float(v[first]), float(v[first + 1]), float(v[first + 2])} * float(w);
}

}  // namespace

Light parseLightOption(const std::string& text) {
    const std::string what = "--light " + text;
    const std::size_t colon = text.find(':');
    const std::optional<Light::Type> type =
        colon == std::string::npos ? std::nullopt : parseNamed(kLightOptionNames, text.substr(0, colon));
    if (!type) throw InputError(what + ": expected TYPE:NUMBERS, TYPE one of " + typeNames());
    const LightForm form = formOf(*type);
    const std::optional<std::vector<double>> v = lightNumbers(std::string_view(text).substr(colon + 1));
    const std::size_t n = v ? v->size() : 0;
    const bool fits = n == form.geometry || n == form.geometry + form.optionalCone ||
                      n == form.geometry + form.optionalCone + 3 || n == form.geometry + form.optionalCone + 4;
    if (!fits || !std::all_of(v->begin(), v->end(), [](double x) { return std::isfinite(x); }))
        throw InputError(what + ": expected " + form.grammar + " (finite numbers)");
    Light light;
    light.type = *type;
    light.color = colorFrom(*v, form.geometry + form.optionalCone, what);
    if (light.type == Light::Type::Point) {
        light.position = vectorAt(*v, 0);
        return light;
    }
    const Vec3 direction = light.type == Light::Type::Spot ? vectorAt(*v, 3) - vectorAt(*v, 0) : vectorAt(*v, 0);
    if (!(length(direction) > 0)) throw InputError(what + ": the light has no direction (zero, or target = position)");
    light.direction = normalize(direction);
    if (light.type == Light::Type::Directional) return light;
    light.position = vectorAt(*v, 0);
    const double cone = n > form.geometry ? (*v)[form.geometry] : 45;
    if (!(cone > 0 && cone <= 90)) throw InputError(what + ": the cone must be above 0 and at most 90 degrees");
    light.outerConeDegrees = float(cone);
    return light;
}

}  // namespace rt::tool::render
