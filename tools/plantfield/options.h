// Command-line options of plantfield, parsed and checked before any GPU work.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace pf {

struct ImageSize {
    uint32_t width = 0;
    uint32_t height = 0;
};

// "1280x720" → {1280, 720}; nullopt for anything else, zero, or > 16384.
std::optional<ImageSize> parseImageSize(const std::string& text);

struct PlantfieldOptions {
    std::string capturePath;
    ImageSize size{1280, 720};
    bool window = false;
    uint32_t frames = 0; // window: stop after this many frames (0 = until closed)
    double time = 0.0;   // scene time of a capture, seconds
    std::string deviceName;
    bool listDevices = false;
    bool validation = false;
    uint32_t samples = 4;
};

// Parses argv. On --help prints usage and returns exit code 0 through
// `exitCode`; on a bad flag prints a clear error and sets exit code 2.
// Returns nullopt whenever the program should exit with *exitCode.
std::optional<PlantfieldOptions> parsePlantfieldOptions(int argc, char** argv, int* exitCode);

} // namespace pf
