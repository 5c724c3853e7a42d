// Command-line options of plantfield, parsed and checked before any GPU work.
#pragma once

#include "engine/scene/scene.h"
#include "tools/field_options.h"

#include <cstdint>
#include <map>
#include <optional>
#include <string>

namespace pf {

// "SPEED[,DIRECTION]" of --wind; nullopt when malformed or the speed is
// outside 0–100 m/s (the direction is left at its default when absent).
std::optional<Wind> parseWind(const std::string& text);

// Frames of a --frames sequence, numbered as its files are: frame_0000.png
// is frame 0. Both ends included.
struct FrameRange {
    uint32_t first = 0;
    uint32_t last = 0;
};

// "A:B" of --frame-range → {A, B}; nullopt when malformed (not two whole
// non-negative numbers around one colon). The order is the caller's check.
std::optional<FrameRange> parseFrameRange(const std::string& text);

// Besides the options both field tools take (tools/field_options.h).
struct PlantfieldOptions : FieldToolOptions {
    std::string capturePath;
    bool window = false;
    bool watch = false;                        // --watch: the window rebuilds when the input's files change
    uint32_t frames = 0;                       // window: stop after this many; headless: this many into outDir, video
    double fps = 30.0;                         // scene seconds per frame of a --frames sequence: 1/fps
    std::string outDir;                        // --frames sequence: DIR/frame_0000.png …
    std::string videoPath;                     // --frames sequence: encoded by ffmpeg into this .mp4, .mkv or .mov
    std::optional<FrameRange> frameRange;      // --frame-range: only these frames of the sequence are written
    std::optional<uint64_t> instances;         // exactly this many generated plants, at the scene's densities
    bool densify = false;                      // --instances on the scene's terrain, distances scaled instead
    bool stats = false;                        // print the frame's JSON statistics on stdout
    bool physicsCheck = false;                 // run GPU and CPU physics side by side, print their deviation as JSON
    std::string exportPath;                    // --export: the field as glTF (.glb or .gltf), built on the CPU, no GPU
    std::string placementsPath;                // --export-placements: every plant as .csv or .json
    bool gpuInstancing = true;                 // false (--no-gpu-instancing): --export writes one node per plant
    std::optional<uint32_t> forcedLod;         // draw every visible plant at this LOD
    std::optional<float> windSpeed;            // replaces the scene's wind speed (m/s)
    std::optional<float> windDirectionDegrees; // and direction, clockwise from north (-z) toward +x
    std::optional<uint32_t> jointBudget;       // replaces the scene's physics.joint_budget
    bool shadowCache = true;                   // false: every frame draws its static shadow casters again
    bool listDevices = false;
    // --render-scale: the window renders at this share of its size; nullopt
    // (auto) lets engine/window/render_scale.h choose it from frame times.
    std::optional<float> renderScale;
    // --plant: one plant on flat ground instead of a scene (tools/plantfield/plant_preview.h)
    std::string plantPath;                      // an L-system file or a vlab object folder
    std::optional<float> plantHeight;           // --plant-height: metres it is scaled to; empty: its own units
    std::optional<uint32_t> plantSteps;         // --steps: derivation length instead of the file's
    std::map<std::string, double> plantDefines; // -D NAME=VALUE
    double orbitDegrees = 0.0;                  // --orbit: the camera's place around it, from +z toward +x
    double orbitSpeed = 0.0;                    // --orbit-speed: degrees a scene second
};

// --export or --export-placements: write files of the field, render nothing.
inline bool exportsField(const PlantfieldOptions& o) { return !o.exportPath.empty() || !o.placementsPath.empty(); }

// Parses argv. On --help prints usage and returns exit code 0 through
// `exitCode`; on a bad flag prints a clear error and sets exit code 2.
// Returns nullopt whenever the program should exit with *exitCode.
std::optional<PlantfieldOptions> parsePlantfieldOptions(int argc, char** argv, int* exitCode);

} // namespace pf
