#include "lsystem/vlab/color_files.h"

#include "lsystem/common/file_reader.h"

namespace lsys::vlab {

namespace {

constexpr size_t kColorMapBytes = 256 * 3;      // cpfg's irisGL.c, load_in_colormaps: 256 RGB triples
constexpr size_t kMaterialRecordBytes = 1 + 14; // load_in_materials: the index, then struct material_load_type
// Larger than any colour file: a material file of all 256 indices is 3840 bytes.
constexpr size_t kMaxColorFileBytes = size_t(1) << 20;

float unit(std::string_view bytes, size_t at) { return static_cast<unsigned char>(bytes[at]) / 255.0f; }

glm::vec3 rgb(std::string_view bytes, size_t at) { return {unit(bytes, at), unit(bytes, at + 1), unit(bytes, at + 2)}; }

// The file's bytes; none, and `result.error` saying why, if it cannot be read.
std::optional<std::string> readBytes(const std::filesystem::path& path, std::string_view kind,
                                     ColorReadResult& result) {
    std::vector<Diagnostic> unread;
    std::optional<std::string> bytes = readTextFileOf(kind, path, kMaxColorFileBytes, unread);
    if (!bytes) result.error = std::move(unread.front());
    return bytes;
}

void refuse(const std::filesystem::path& path, ColorReadResult& result, std::string message, std::string expected) {
    result.error = Diagnostic{path.string(), 0, 0, std::move(message), std::move(expected)};
}

} // namespace

// cpfg reads 256 triples whatever the file's size (a shorter file leaves
// entries of whatever the memory held) and draws with the colour itself
// (glColor3ub in platformQt.cpp, my_color): it is the ambient and diffuse
// colour here, for a renderer that lights what it draws.
ColorReadResult readColorMap(const std::filesystem::path& path) {
    ColorReadResult result;
    const std::optional<std::string> bytes = readBytes(path, "colour map", result);
    if (!bytes) return result;
    if (bytes->size() < kColorMapBytes) {
        refuse(path, result,
               "the colour map " + path.string() + " has " + std::to_string(bytes->size()) +
                   " bytes, fewer than 256 colours",
               std::to_string(kColorMapBytes) + " bytes: red, green and blue bytes of colours 0 to 255");
        return result;
    }
    for (size_t i = 0; i < result.colors.size(); ++i) {
        ColorEntry& entry = result.colors[i];
        entry.diffuse = entry.ambient = rgb(*bytes, 3 * i);
        entry.defined = true;
    }
    return result;
}

// A record per material: its index, transparency, ambient, diffuse,
// emissive and specular RGB, and shininess, each one byte (cpfg's irisGL.c,
// load_in_materials). Colours are byte / 255; the shininess is the byte
// itself, OpenGL's specular exponent; a later record of an index replaces
// an earlier one. An index without a record keeps cpfg's default material,
// white diffuse only (irisGL.c, default_material), and defined = false.
ColorReadResult readMaterialFile(const std::filesystem::path& path) {
    ColorReadResult result;
    const std::optional<std::string> bytes = readBytes(path, "material", result);
    if (!bytes) return result;
    if (bytes->size() % kMaterialRecordBytes != 0) {
        refuse(path, result,
               "the material file " + path.string() + " has " + std::to_string(bytes->size()) +
                   " bytes, not a whole number of 15-byte materials",
               "records of an index byte, then transparency, ambient RGB, diffuse RGB, emissive RGB, specular RGB "
               "and shininess bytes");
        return result;
    }
    for (ColorEntry& entry : result.colors) entry.diffuse = glm::vec3(1.0f);
    for (size_t at = 0; at < bytes->size(); at += kMaterialRecordBytes) {
        ColorEntry& entry = result.colors[static_cast<unsigned char>((*bytes)[at])];
        entry.opacity = 1.0f - unit(*bytes, at + 1);
        entry.ambient = rgb(*bytes, at + 2);
        entry.diffuse = rgb(*bytes, at + 5);
        entry.emissive = rgb(*bytes, at + 8);
        entry.specular = rgb(*bytes, at + 11);
        entry.shininess = static_cast<unsigned char>((*bytes)[at + 14]);
        entry.defined = true;
    }
    return result;
}

} // namespace lsys::vlab
