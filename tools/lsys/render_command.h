// lsys render: an image of one plant ray traced on the CPU through its
// InstanceGraph, its flattened plant or its objects expanded lazily
// (lsystem/raytrace/render.h, docs/RAYTRACING.md).
#pragma once

#include <CLI/CLI.hpp>

#include "tools/lsys/command.h"

namespace tools {

// Adds the `render` subcommand and its options to `app`.
Command addRenderCommand(CLI::App& app);

} // namespace tools
