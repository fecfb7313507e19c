#include "accel/settings.h"

namespace rt {

std::optional<AccelKind> parseAccelKind(const std::string& name) {
    if (name == "naive") return AccelKind::Naive;
    if (name == "bsp") return AccelKind::Bsp;
    if (name == "kd") return AccelKind::Kd;
    return std::nullopt;
}

const char* accelKindName(AccelKind kind) {
    switch (kind) {
        case AccelKind::Naive: return "naive";
        case AccelKind::Bsp: return "bsp";
        case AccelKind::Kd: return "kd";
    }
    return "?";
}

std::optional<KdSplitMethod> parseKdSplitMethod(const std::string& name) {
    if (name == "sweep") return KdSplitMethod::Sweep;
    if (name == "sort") return KdSplitMethod::Sort;
    if (name == "sample") return KdSplitMethod::Sample;
    return std::nullopt;
}

const char* kdSplitMethodName(KdSplitMethod method) {
    switch (method) {
        case KdSplitMethod::Sweep: return "sweep";
        case KdSplitMethod::Sort: return "sort";
        case KdSplitMethod::Sample: return "sample";
    }
    return "?";
}

}  // namespace rt
