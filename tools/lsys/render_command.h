// lsys render: an image of one plant ray traced on the CPU through its
// InstanceGraph, its flattened plant or its objects expanded lazily
// (lsystem/raytrace/render.h, docs/RAYTRACING.md).
#pragma once

#include <functional>

#include <CLI/CLI.hpp>

namespace tools {

struct RenderCommand {
    CLI::App* command = nullptr;
    std::function<int()> run; // once the app has parsed `command`; the exit code
};

// Adds the `render` subcommand and its options to `app`.
RenderCommand addRenderCommand(CLI::App& app);

} // namespace tools
