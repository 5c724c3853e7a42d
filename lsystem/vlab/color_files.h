#pragma once
// cpfg's colours: a colour map (.map, 256 RGB byte triples, index i at bytes
// 3i..3i+2) or a material file (.mat, records of 15 bytes: the index, then
// transparency, ambient RGB, diffuse RGB, emissive RGB, specular RGB and
// shininess, each a byte), read as cpfg's irisGL.c reads them. Either gives
// the 256 entries the turtle's ; and , index.

#include <array>
#include <filesystem>
#include <optional>
#include <string>

#include <glm/vec3.hpp>

#include "lsystem/common/error.h"

namespace lsys::vlab {

struct ColorEntry {
    glm::vec3 diffuse{0.0f}; // the colour a colour map gives; a material's diffuse
    glm::vec3 ambient{0.0f}; // of a material; a colour map's entry has its colour here too
    glm::vec3 emissive{0.0f};
    glm::vec3 specular{0.0f};
    float shininess = 0.0f;
    float opacity = 1.0f; // 1 - transparency / 255
    bool defined = false; // a material file may leave indices out
};

using ColorTable = std::array<ColorEntry, 256>;

struct ColorReadResult {
    ColorTable colors{};
    std::optional<Diagnostic> error; // the file and what is wrong with it
};

ColorReadResult readColorMap(const std::filesystem::path& path);
ColorReadResult readMaterialFile(const std::filesystem::path& path);

} // namespace lsys::vlab
