#include "options.h"

#include "engine/device.h"
#include "engine/image.h"

#include <CLI/CLI.hpp>

#include <charconv>
#include <iostream>

namespace pf {
namespace {

constexpr uint32_t kMaxImageSide = 16384;

bool parseSide(const char* first, const char* last, uint32_t& out) {
    auto [end, ec] = std::from_chars(first, last, out);
    return ec == std::errc() && end == last && out > 0 && out <= kMaxImageSide;
}

} // namespace

std::optional<ImageSize> parseImageSize(const std::string& text) {
    const size_t x = text.find('x');
    if (x == std::string::npos || x == 0 || x + 1 == text.size()) return std::nullopt;
    ImageSize size;
    const char* s = text.data();
    if (!parseSide(s, s + x, size.width) || !parseSide(s + x + 1, s + text.size(), size.height)) return std::nullopt;
    return size;
}

std::optional<PlantfieldOptions> parsePlantfieldOptions(int argc, char** argv, int* exitCode) {
    PlantfieldOptions o;
    o.validation = validationWantedByDefault();
    std::string sizeText = "1280x720";

    CLI::App app{"plantfield: renders a field of L-system plants, in a window or headless to PNG."};
    app.footer("Examples:\n  plantfield --capture frame.png --size 1280x720\n  plantfield --window\n"
               "Environment: PLANTFIELD_DEVICE picks the device by name, PLANTFIELD_VALIDATION=1 turns on\n"
               "the Khronos validation layer.");
    app.add_option("--capture", o.capturePath, "Render one frame headless and write it to this PNG file");
    app.add_option("--size", sizeText, "Image or window size as WIDTHxHEIGHT (1 to 16384 per side)")
        ->default_str("1280x720");
    app.add_flag("--window", o.window, "Open a window and render in real time");
    app.add_option("--frames", o.frames, "With --window: close after this many frames (0: run until closed)");
    app.add_option("--time", o.time, "Scene time of the frame in seconds")->check(CLI::NonNegativeNumber);
    app.add_option("--device", o.deviceName, "Use the Vulkan device whose name contains this text");
    app.add_flag("--list-devices", o.listDevices, "List the Vulkan devices and exit");
    app.add_flag("--validation,!--no-validation", o.validation,
                 "Enable the Khronos validation layer (default: on in debug builds)");
    app.add_option("--samples", o.samples, "Multisample anti-aliasing samples")
        ->check(CLI::IsMember({1, 2, 4, 8}));

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        if (e.get_exit_code() == 0) {
            *exitCode = app.exit(e);
            return std::nullopt;
        }
        std::cerr << "plantfield: error: " << e.what() << "\nRun 'plantfield --help' for usage.\n";
        *exitCode = 2;
        return std::nullopt;
    }

    auto fail = [&](const std::string& message) {
        std::cerr << "plantfield: error: " << message << "\n";
        *exitCode = 2;
        return std::nullopt;
    };
    const std::optional<ImageSize> size = parseImageSize(sizeText);
    if (!size) return fail("invalid --size '" + sizeText + "': expected WIDTHxHEIGHT with each side 1 to 16384, e.g. 1280x720");
    o.size = *size;
    if (o.listDevices) return o;
    if (o.capturePath.empty() && !o.window)
        return fail("nothing to do: pass --capture FILE.png for a headless frame or --window for real time");
    if (!o.capturePath.empty()) {
        const std::string problem = outputPathProblem(o.capturePath);
        if (!problem.empty()) return fail("cannot write --capture file: " + problem);
    }
    return o;
}

} // namespace pf
