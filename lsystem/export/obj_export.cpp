// Wavefront OBJ writer: always the flat form (OBJ cannot share meshes), one
// object per material, with a .mtl of diffuse colours beside it.
#include <algorithm>
#include <cctype>
#include <charconv>
#include <ostream>
#include <string>
#include <string_view>
#include <type_traits>

#include "lsystem/export/export_detail.h"

namespace lsys::export_detail {
namespace {

// OBJ and MTL names end at whitespace.
std::string objName(const std::vector<Material>& materials, uint32_t material) {
    std::string name = materialName(materials, material);
    std::replace_if(
        name.begin(), name.end(), [](unsigned char c) { return std::isspace(c); }, '_');
    return name;
}

// Builds the text in memory with std::to_chars (the shortest digits that
// read back to the same float), several times faster than ostream's
// formatting for the millions of numbers a plant has; flushes in blocks.
class ObjText {
public:
    explicit ObjText(std::ostream& out) : out_(out) {}

    ObjText& operator<<(std::string_view text) {
        text_ += text;
        return *this;
    }
    ObjText& operator<<(char c) {
        text_ += c;
        return *this;
    }
    template <typename Number>
    requires std::is_arithmetic_v<Number> ObjText& operator<<(Number value) {
        char digits[32];
        text_.append(digits, std::to_chars(digits, digits + sizeof digits, value).ptr);
        if (text_.size() > (1u << 20)) flush();
        return *this;
    }
    void flush() {
        out_.write(text_.data(), std::streamsize(text_.size()));
        text_.clear();
    }

private:
    std::ostream& out_;
    std::string text_;
};

} // namespace

void writeObj(const std::vector<Material>& materials, const std::vector<TriangleMesh>& meshes, std::ostream& objStream,
              std::ostream& mtlStream, const std::string& mtlFileName) {
    ObjText obj(objStream), mtl(mtlStream);
    obj << "# plantfield plant: metres, y up\nmtllib " << mtlFileName << "\n";
    for (uint32_t m = 0; m < materials.size(); ++m) {
        const glm::vec3& albedo = materials[m].albedo;
        mtl << "newmtl " << objName(materials, m) << "\nKd " << albedo.r << ' ' << albedo.g << ' ' << albedo.b
            << "\n\n";
    }
    // OBJ indices are 1-based and count every vertex written before them.
    uint32_t base = 1;
    for (uint32_t m = 0; m < meshes.size(); ++m) {
        const TriangleMesh& mesh = meshes[m];
        if (mesh.indices.empty()) continue;
        obj << "o " << objName(materials, m) << "\nusemtl " << objName(materials, m) << "\n";
        for (const glm::vec3& p : mesh.positions) obj << "v " << p.x << ' ' << p.y << ' ' << p.z << '\n';
        for (const glm::vec2& t : mesh.uvs) obj << "vt " << t.x << ' ' << t.y << '\n';
        for (const glm::vec3& n : mesh.normals) obj << "vn " << n.x << ' ' << n.y << ' ' << n.z << '\n';
        for (size_t t = 0; t < mesh.indices.size(); t += 3) {
            obj << 'f';
            for (size_t corner = t; corner < t + 3; ++corner) {
                const uint32_t i = base + mesh.indices[corner];
                obj << ' ' << i << '/' << i << '/' << i;
            }
            obj << '\n';
        }
        base += mesh.vertexCount();
    }
    obj.flush();
    mtl.flush();
    if (!objStream || !mtlStream) throw std::runtime_error("writing the OBJ stream failed");
}

} // namespace lsys::export_detail
