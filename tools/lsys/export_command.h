// lsys export FILE [-n STEPS] [--seed S] [-D NAME=VALUE]... [--dialect D] -o OUT.gltf|.glb|.obj
//   [--flat|--instanced] [--randomness K] [--granularity G] [--max-gltf-nodes N]
//   [--geometry drawn|frusta|tubes] [--generalized-cylinders] [--max-modules N]
//   [--sides N] [--skeleton|--no-skeleton] [--height H]:
// writes a plant, a component plant or a ramification tree as glTF or OBJ
// (docs/EXPORT.md).
#pragma once

#include <CLI/CLI.hpp>

#include "tools/lsys/command.h"

namespace tools {

// Adds the `export` subcommand and its options to `app`.
Command addExportCommand(CLI::App& app);

} // namespace tools
