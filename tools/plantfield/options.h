// Command-line options of plantfield, parsed and checked before any GPU work.
#pragma once

#include "engine/field/sun_shadows.h"
#include "engine/scene/scene.h"
#include "engine/vk/antialiasing.h"
#include "lsystem/common/memory_budget.h"

#include <cstdint>
#include <map>
#include <optional>
#include <string>

namespace CLI {
class App;
class Option;
} // namespace CLI

namespace pf {

struct ImageSize {
    uint32_t width = 0;
    uint32_t height = 0;
};

// "1280x720" → {1280, 720}; nullopt for anything else, zero, or > 16384.
std::optional<ImageSize> parseImageSize(const std::string& text);

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

// Accepts only finite numbers from min to max (both included). CLI11's
// Range and NonNegativeNumber compare with < and >, which NaN passes, and
// infinity passes an open upper end.
void checkFiniteIn(CLI::Option& option, double min, double max);

// The latest scene time --time takes: the shaders' float time still steps by
// under 10 ms there (2^-7 s at 10^5 s), so the wind's motion stays smooth.
inline constexpr double kMaxSceneTime = 100000.0;

// --aa METHOD and --samples S, the same on plantfield and plantbench: FXAA
// by default; the MSAA sample count only with --aa msaa.
struct AntialiasFlags {
    std::string method = antialiasMethodName(AntialiasMethod::fxaa);
    std::optional<uint32_t> samples;
};
void addAntialiasOptions(CLI::App& app, AntialiasFlags& flags);
// --shadows map|raytraced|none and --no-shadows (none), the same on both.
void addSunShadowsOptions(CLI::App& app, SunShadows& shadows);
// What the flags choose, or nullopt with `problem` set when --samples comes
// with another method than msaa.
std::optional<Antialiasing> antialiasingOf(const AntialiasFlags& flags, std::string* problem);

// The scene a tool renders when none is named: scenes/default.json of the
// data folder (tools/data_dir.h: PLANTFIELD_DATA_DIR, an installed tree's
// share/plantfield/data, or the source tree's data/).
std::string defaultScenePath();

struct PlantfieldOptions {
    std::string scenePath;
    std::string capturePath;
    ImageSize size{1280, 720};
    bool window = false;
    bool watch = false;                        // --watch: the window rebuilds when the input's files change
    uint32_t frames = 0;                       // window: stop after this many; headless: this many into outDir, video
    double fps = 30.0;                         // scene seconds per frame of a --frames sequence: 1/fps
    std::string outDir;                        // --frames sequence: DIR/frame_0000.png …
    std::string videoPath;                     // --frames sequence: encoded by ffmpeg into this .mp4, .mkv or .mov
    std::optional<FrameRange> frameRange;      // --frame-range: only these frames of the sequence are written
    double time = 0.0;                         // scene time of the (first) frame, seconds
    std::optional<uint64_t> instances;         // exactly this many generated plants, at the scene's densities
    bool densify = false;                      // --instances on the scene's terrain, distances scaled instead
    std::optional<uint32_t> seed;              // replaces the scene's seed
    bool stats = false;                        // print the frame's JSON statistics on stdout
    bool physicsCheck = false;                 // run GPU and CPU physics side by side, print their deviation as JSON
    std::string exportPath;                    // --export: the field as glTF (.glb or .gltf), built on the CPU, no GPU
    std::string placementsPath;                // --export-placements: every plant as .csv or .json
    bool gpuInstancing = true;                 // false (--no-gpu-instancing): --export writes one node per plant
    std::optional<uint32_t> forcedLod;         // draw every visible plant at this LOD
    std::optional<float> windSpeed;            // replaces the scene's wind speed (m/s)
    std::optional<float> windDirectionDegrees; // and direction, clockwise from north (-z) toward +x
    std::optional<uint32_t> jointBudget;       // replaces the scene's physics.joint_budget
    SunShadows shadows = SunShadows::shadowMap;
    bool shadowCache = true;       // false: every frame draws its static shadow casters again
    bool occlusionCulling = false; // --occlusion: plants behind the depth pyramid are not drawn
    bool clusters = true;          // false: every plant through the per-plant cull, no far canopy (--no-clusters)
    std::string deviceName;
    bool listDevices = false;
    bool validation = false;
    Antialiasing antialiasing;
    // --render-scale: the window renders at this share of its size; nullopt
    // (auto) lets engine/window/render_scale.h choose it from frame times.
    std::optional<float> renderScale;
    lsys::MemoryBudget memory; // --memory-budget: terrain, placement, uploads
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
