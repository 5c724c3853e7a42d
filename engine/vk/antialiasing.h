// How a frame's edges are smoothed: what the tools' --aa and --samples choose
// (docs/FIELD.md, Anti-aliasing). No Vulkan types, so option parsing and
// plantbench's memory estimate use it without a device.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace pf {

enum class AntialiasMethod {
    fxaa, // the colour pass draws one sample a pixel, then the FXAA pass (fxaa_pass.h) smooths its edges
    msaa, // the colour pass draws msaaSamples a pixel, averaged (resolved) as it ends
    none, // one sample a pixel, as drawn
};

struct Antialiasing {
    AntialiasMethod method = AntialiasMethod::fxaa;
    uint32_t msaaSamples = 4; // with msaa: 2, 4 or 8, lowered to what the device supports
};

// Samples a pixel of the colour pass: msaaSamples with msaa, 1 otherwise.
inline uint32_t colorPassSamples(const Antialiasing& aa) {
    return aa.method == AntialiasMethod::msaa ? aa.msaaSamples : 1;
}

// The --aa values: "fxaa", "msaa", "none".
const char* antialiasMethodName(AntialiasMethod method);
std::optional<AntialiasMethod> antialiasMethodNamed(std::string_view name);
// For reports and titles: "FXAA", "4x MSAA", "no anti-aliasing".
std::string antialiasingText(const Antialiasing& aa);

} // namespace pf
