// Where the field's sun visibility comes from, and the names the tools
// take and print for it (plantfield and plantbench --shadows).
#pragma once

#include <optional>
#include <string_view>

namespace pf {

// Nowhere (every surface facing the sun lit), the shadow map (shadow_map.h),
// or a ray a pixel through the field's graph for the plant meshes and the
// ground near the camera, the far impostors and canopy lit with their baked
// shadows (raytraced_sun_pass.h).
enum class SunShadows { none, map, raytraced };

// "none", "map", "raytraced". Inline: the tools' option parsing links no renderer.
inline std::string_view sunShadowsName(SunShadows shadows) {
    switch (shadows) {
    case SunShadows::none: return "none";
    case SunShadows::map: return "map";
    case SunShadows::raytraced: return "raytraced";
    }
    return "";
}

inline std::optional<SunShadows> sunShadowsNamed(std::string_view name) {
    for (SunShadows shadows : {SunShadows::none, SunShadows::map, SunShadows::raytraced})
        if (sunShadowsName(shadows) == name) return shadows;
    return std::nullopt;
}

} // namespace pf
