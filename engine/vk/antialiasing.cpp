#include "engine/vk/antialiasing.h"

#include <array>
#include <utility>

namespace pf {
namespace {

constexpr std::array<std::pair<const char*, AntialiasMethod>, 3> kMethodNames = {
    {{"fxaa", AntialiasMethod::fxaa}, {"msaa", AntialiasMethod::msaa}, {"none", AntialiasMethod::none}}};

} // namespace

const char* antialiasMethodName(AntialiasMethod method) {
    for (const auto& [name, m] : kMethodNames)
        if (m == method) return name;
    return "unknown";
}

std::optional<AntialiasMethod> antialiasMethodNamed(std::string_view name) {
    for (const auto& [n, method] : kMethodNames)
        if (name == n) return method;
    return std::nullopt;
}

std::string antialiasingText(const Antialiasing& aa) {
    switch (aa.method) {
    case AntialiasMethod::fxaa: return "FXAA";
    case AntialiasMethod::msaa: return std::to_string(aa.msaaSamples) + "x MSAA";
    case AntialiasMethod::none: return "no anti-aliasing";
    }
    return "unknown anti-aliasing";
}

} // namespace pf
