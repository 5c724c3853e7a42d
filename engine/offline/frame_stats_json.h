// The statistics of an offline renderer's last frame as JSON: what
// plantfield --stats prints (docs/FIELD.md) and the Python module's
// Renderer.stats() returns.
#pragma once

#include "engine/offline/offline_renderer.h"

#include <string>

namespace pf {

// `scene` names what was rendered (the scene file, or the previewed plant).
std::string frameStatsJson(const OfflineRenderer& renderer, const std::string& scene);

} // namespace pf
