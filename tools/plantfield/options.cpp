#include "options.h"
#include "output_check.h"

#include "engine/image/video_encoder.h"
#include "shaders/shared/field_layouts.h"

#include <CLI/CLI.hpp>
#include <plantfield_version.h>

#include <cctype>
#include <charconv>
#include <filesystem>
#include <initializer_list>
#include <iostream>
#include <string_view>
#include <vector>

namespace pf {

std::optional<Wind> parseWind(const std::string& text) {
    const size_t comma = text.find(',');
    Wind wind;
    const std::string_view all(text);
    const std::optional<float> speed = finiteNumber<float>(all.substr(0, comma));
    if (!speed || *speed < 0.0f || *speed > 100.0f) return std::nullopt;
    wind.speed = *speed;
    if (comma != std::string::npos) {
        const std::optional<float> direction = finiteNumber<float>(all.substr(comma + 1));
        if (!direction) return std::nullopt;
        wind.directionDegrees = *direction;
    }
    return wind;
}

std::optional<FrameRange> parseFrameRange(const std::string& text) {
    const size_t colon = text.find(':');
    if (colon == std::string::npos) return std::nullopt;
    FrameRange range;
    const char* s = text.data();
    const auto whole = [](const char* first, const char* last, uint32_t& out) {
        const auto [end, ec] = std::from_chars(first, last, out);
        return first != last && ec == std::errc() && end == last;
    };
    if (!whole(s, s + colon, range.first) || !whole(s + colon + 1, s + text.size(), range.last)) return std::nullopt;
    return range;
}

std::optional<PlantfieldOptions> parsePlantfieldOptions(int argc, char** argv, int* exitCode) {
    PlantfieldOptions o;

    CLI::App app{"plantfield: renders a field of L-system plants (a scene file, docs/SCENE_FORMAT.md), in a window\n"
                 "or headless to PNG."};
    app.set_version_flag("--version", std::string("plantfield ") + kPlantfieldVersion);
    app.footer("Examples:\n"
               "  plantfield --capture frame.png                      the default forest at 1280x720\n"
               "  plantfield data/scenes/default.json --window        fly through it (docs/WINDOW.md)\n"
               "  plantfield --instances 100000 --stats               one frame of 100 000 plants: JSON statistics\n"
               "  plantfield data/scenes/valley.json --capture v.png  a million plants on 2 km x 2 km\n"
               "  plantfield --frames 60 --fps 30 --out-dir seq       two seconds of frames\n"
               "  plantfield --frames 60 --frame-range 30:59 --out-dir seq   its second half only\n"
               "  plantfield --capture frame.png --aa msaa            4x multisampling instead of FXAA\n"
               "  plantfield --export field.glb                       the default forest as glTF, no GPU needed\n"
               "  plantfield --plant data/plants/spruce.lsys --capture s.png   one plant, framed by an orbit camera\n"
               "  plantfield --plant my_plant.lsys --window --watch   regrown in the window at each save\n" +
               std::string(kFieldToolEnvironment));
    FieldToolTexts shared;
    addFieldToolOptions(app, o, shared);
    app.add_option("--plant", o.plantPath,
                   "Preview one plant instead of a scene: an L-system file (.lsys, .l), a vlab object folder,\n"
                   "a ramification tree (.ram.json) or a component plant (.comp.json),\n"
                   "one plant at the origin in its own units on flat ground, no wind unless --wind, framed by an\n"
                   "orbit camera (docs/PLANT_PREVIEW.md)")
        ->type_name("FILE|DIR");
    checkFiniteIn(*app.add_option("--plant-height", o.plantHeight,
                                  "With --plant: scale the plant so its top is this many metres high"),
                  1e-6, 1e6);
    app.add_option("--steps", o.plantSteps, "With --plant: derivation steps instead of the file's derivation length")
        ->check(CLI::Range(0, 1000));
    std::vector<std::string> defineTexts;
    app.add_option("-D,--define", defineTexts, "With --plant: override a #define constant: NAME=VALUE (repeatable)");
    checkFiniteIn(*app.add_option("--orbit", o.orbitDegrees,
                                  "With --plant: the camera's place around the plant in degrees, from the south\n"
                                  "(+z) toward the east (+x); 20 degrees above the plant's centre"),
                  -36000.0, 36000.0);
    checkFiniteIn(*app.add_option("--orbit-speed", o.orbitSpeed,
                                  "With --plant: degrees the camera turns around the plant a scene second (--frames)"),
                  -36000.0, 36000.0);
    app.add_option("--capture", o.capturePath, "Render one frame headless and write it to this PNG file");
    app.add_flag("--window", o.window, "Open a window: camera-path playback and free flight");
    app.add_flag("--watch", o.watch,
                 "With --window: rebuild whenever the scene file, a plant file it uses (L-system, vlab object\n"
                 "files) or the --plant file or folder changes on disk, keeping the camera; an error is shown in\n"
                 "the window and on stderr while the last good build stays drawn (docs/PLANT_PREVIEW.md)");
    std::string renderScaleText;
    app.add_option("--render-scale", renderScaleText,
                   "With --window: render at this share of the window's size, 0.25 to 1, or auto (default): the\n"
                   "share drops in steps of 1/8 to 1/2 while frames take over 1/15 s and rises again when they\n"
                   "have time to spare, starting at 1/2 on a CPU device and at 1 on a GPU; the frame is blitted\n"
                   "up to the window (docs/WINDOW.md)")
        ->type_name("S|auto");
    app.add_option("--frames", o.frames,
                   "Headless: render this many frames into --out-dir and/or --video; with --window: close after\n"
                   "this many");
    checkFiniteIn(*app.add_option("--fps", o.fps, "Frames per scene second of a --frames sequence"), 0.1, 1000.0);
    app.add_option("--out-dir", o.outDir, "Folder of a --frames sequence (frame_0000.png, ...), created if missing");
    app.add_option("--video", o.videoPath,
                   "With --frames N: encode the frames (with --frame-range, those) into FILE.mp4, .mkv or .mov,\n"
                   "H.264 at --fps, with ffmpeg as they are rendered (docs/FARM.md)")
        ->type_name("FILE");
    std::string frameRangeText;
    app.add_option("--frame-range", frameRangeText,
                   "With --frames N and --out-dir DIR or --video FILE: write only frames A to B of the sequence (both "
                   "included,\n"
                   "numbered from 0 as the files are: 0:0 is frame_0000.png), the same bytes as the whole\n"
                   "run's; the frames before A are rendered too, not written, for the motion they carry\n"
                   "(docs/FARM.md)")
        ->type_name("A:B");
    app.add_option("--instances", o.instances,
                   "Exactly this many generated plants at the scene's densities: they fill a square around the\n"
                   "origin that grows with N, the noise terrain growing with it (hand-placed plants come on top)")
        ->check(CLI::Range(uint64_t(1), uint64_t(FIELD_MAX_INSTANCES)));
    app.add_flag("--densify", o.densify,
                 "With --instances: keep the scene's terrain and scale every plant distance to fit N on it");
    app.add_flag(
        "--stats", o.stats,
        "Print JSON statistics of the (last) frame: plants per LOD, culled, occluded, draws, triangles, GPU ms per\n"
        "pass");
    app.add_flag("--physics-check", o.physicsCheck,
                 "Simulate one skeleton of every plant model for 600 sub-steps on the GPU and the CPU and print\n"
                 "JSON: joints, steps, max_deviation_rad (exit 1 when 1e-3 rad or more), gpu_ms, cpu_ms");
    app.add_option("--export", o.exportPath,
                   "Write the field as glTF 2.0 (.glb or .gltf) and exit, no GPU needed: the terrain, one mesh per\n"
                   "plant model, materials, and the plants through EXT_mesh_gpu_instancing (docs/EXPORT.md)")
        ->type_name("FILE");
    app.add_flag("!--no-gpu-instancing", o.gpuInstancing,
                 "With --export: one plain node per plant instead of EXT_mesh_gpu_instancing, for loaders that\n"
                 "ignore the extension (Blender 3.4)");
    app.add_option("--export-placements", o.placementsPath,
                   "Write every plant (species, model, x, y, z, qx, qy, qz, qw, scale) as .csv or .json and exit")
        ->type_name("FILE");
    std::string windText;
    app.add_option("--wind", windText,
                   "Replace the scene's wind: SPEED[,DIRECTION] in m/s and degrees clockwise from north");
    app.add_option("--joint-budget", o.jointBudget,
                   "Replace the scene's joint budget: joints of the nearest plants simulated each with their own\n"
                   "state (0 to 10000000; farther plants share per-species copies)")
        ->check(CLI::Range(uint32_t(0), kMaxJointBudget));
    app.add_option("--lod", o.forcedLod, "Draw every visible plant at this LOD: 0 full, 1 reduced, 2 impostor")
        ->check(CLI::Range(0, 2));
    app.add_flag("!--no-shadow-cache", o.shadowCache,
                 "Draw the shadow map's static casters again every frame instead of keeping them while the camera "
                 "stays near");
    app.add_flag("--list-devices", o.listDevices, "List the Vulkan devices and exit");

    if (!parseToolCommandLine(app, argc, argv, "plantfield", exitCode)) return std::nullopt;
    auto fail = [&](const std::string& message) {
        reportBadOption("plantfield", message, exitCode);
        return std::nullopt;
    };
    const std::string problem = finishFieldToolOptions(shared, o);
    if (!problem.empty()) return fail(problem);
    if (!windText.empty()) {
        const std::optional<Wind> wind = parseWind(windText);
        if (!wind)
            return fail("invalid --wind '" + windText +
                        "': expected SPEED[,DIRECTION], e.g. 12 or 12,270, speed 0 to 100 m/s");
        o.windSpeed = wind->speed;
        if (windText.find(',') != std::string::npos) o.windDirectionDegrees = wind->directionDegrees;
    }
    if (!renderScaleText.empty() && renderScaleText != "auto") {
        const std::optional<float> share = finiteNumber<float>(renderScaleText);
        if (!share || *share < 0.25f || *share > 1.0f)
            return fail("invalid --render-scale '" + renderScaleText + "': expected auto or a share 0.25 to 1");
        o.renderScale = *share;
    }
    if (o.listDevices) return o;
    const bool plant = !o.plantPath.empty();
    for (const std::string& text : defineTexts) {
        const size_t equals = text.find('=');
        const std::optional<double> value = equals == std::string::npos
                                                ? std::nullopt
                                                : finiteNumber<double>(std::string_view(text).substr(equals + 1));
        if (equals == 0 || !value)
            return fail("invalid -D '" + text + "': expected NAME=VALUE with a number, e.g. -D ANGLE=30");
        o.plantDefines[text.substr(0, equals)] = *value;
    }
    if (plant && app.count("scene") > 0)
        return fail("--plant previews one plant instead of a scene: give either a scene file or --plant, not both");
    if (!plant && (o.plantHeight || o.plantSteps || !defineTexts.empty() || app.count("--orbit") > 0 ||
                   app.count("--orbit-speed") > 0))
        return fail("--plant-height, --steps, -D, --orbit and --orbit-speed are for --plant FILE");
    if (plant && (o.plantSteps || !defineTexts.empty()) && isPlantModelFile(o.plantPath))
        return fail("--steps and -D derive an L-system; " + o.plantPath +
                    " is a model, built rather than derived (--seed replaces its seed)");
    if (plant && o.instances) return fail("--instances is for scenes: --plant previews one plant");
    const bool sequence = !o.window && o.frames > 0;
    if (!frameRangeText.empty()) {
        if (!sequence)
            return fail("--frame-range needs a headless sequence: --frames N with --out-dir DIR or --video FILE, "
                        "no --window");
        o.frameRange = parseFrameRange(frameRangeText);
        if (!o.frameRange)
            return fail("invalid --frame-range '" + frameRangeText +
                        "': expected A:B, the first and the last frame numbered from 0 as frame_0000.png, e.g. 0:99");
        if (o.frameRange->first > o.frameRange->last)
            return fail("invalid --frame-range '" + frameRangeText + "': the first frame comes after the last");
        if (o.frameRange->last >= o.frames)
            return fail("--frame-range " + frameRangeText + " ends past the sequence: --frames " +
                        std::to_string(o.frames) + " numbers its frames 0 to " + std::to_string(o.frames - 1));
    }
    if (exportsField(o) && (!o.capturePath.empty() || o.window || o.frames > 0 || o.stats || o.physicsCheck))
        return fail("--export and --export-placements are a mode of their own: no --capture, --frames, --stats, "
                    "--physics-check or --window");
    if (!o.gpuInstancing && o.exportPath.empty()) return fail("--no-gpu-instancing needs --export FILE.glb|.gltf");
    if (o.physicsCheck && (!o.capturePath.empty() || o.window || o.frames > 0 || o.stats))
        return fail("--physics-check is a mode of its own: no --capture, --frames, --stats or --window");
    if (o.watch && !o.window)
        return fail("--watch needs --window: it rebuilds what the window shows when its files change");
    if (o.capturePath.empty() && !o.window && !sequence && !o.stats && !o.physicsCheck && !exportsField(o))
        return fail("nothing to do: pass --capture FILE.png, --frames N --out-dir DIR, --stats, --physics-check, "
                    "--export FILE.glb or --window");
    if (o.densify && !o.instances) return fail("--densify needs --instances N");
    if (sequence && o.outDir.empty() && o.videoPath.empty())
        return fail("--frames without --window needs --out-dir DIR for the images or --video FILE");
    if (!o.outDir.empty() && !sequence) return fail("--out-dir needs --frames N (and no --window)");
    if (!o.videoPath.empty() && !sequence) return fail("--video needs --frames N (and no --window)");
    if (!renderScaleText.empty() && !o.window)
        return fail("--render-scale is for --window: captures and sequences render at --size");
    if (plant) {
        std::error_code error;
        if (!std::filesystem::is_regular_file(o.plantPath, error) && !std::filesystem::is_directory(o.plantPath, error))
            return fail("plant '" + o.plantPath +
                        "' does not exist: --plant takes an L-system file or a vlab object folder");
    } else if (!std::filesystem::is_regular_file(o.scenePath))
        return fail("scene file '" + o.scenePath + "' does not exist or is not a file");
    if (!o.videoPath.empty() && !videoMuxerFor(o.videoPath))
        return fail("--video '" + o.videoPath + "': unknown extension (expected .mp4, .mkv or .mov)");
    const auto extensionIn = [](const std::string& path, std::initializer_list<const char*> allowed) {
        std::string extension = std::filesystem::path(path).extension().string();
        for (char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
        for (const char* a : allowed)
            if (extension == a) return true;
        return false;
    };
    if (!o.exportPath.empty() && !extensionIn(o.exportPath, {".glb", ".gltf"}))
        return fail("invalid --export file '" + o.exportPath + "': expected a .glb or .gltf file");
    if (!o.placementsPath.empty() && !extensionIn(o.placementsPath, {".csv", ".json"}))
        return fail("invalid --export-placements file '" + o.placementsPath + "': expected a .csv or .json file");
    if (const std::string problem = outputsProblem(o); !problem.empty()) return fail(problem);
    return o;
}

} // namespace pf
