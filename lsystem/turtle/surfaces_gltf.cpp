// Reads predefined surfaces from glTF 2.0 files with tinygltf (the compiled
// Debian library: TINYGLTF_IMPLEMENTATION is defined inside it, never here).

#include <tiny_gltf.h>

#include <nlohmann/json.hpp>

#include <cctype>
#include <cstring>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "lsystem/common/file_reader.h"
#include "lsystem/turtle/surfaces.h"

namespace lsys {

namespace {

struct MeshFileReader {
    const tinygltf::Model& model;
    const std::filesystem::path& file;

    [[noreturn]] void fail(const std::string& what) const {
        throw SurfaceError("mesh file " + file.string() + ": " + what);
    }

    // The accessor's elements as vectors of N floats (float components, or
    // normalised unsigned byte/short as glTF allows for uvs); none for index -1.
    template <int N>
    std::vector<glm::vec<N, float>> vectors(int accessorIndex) const {
        std::vector<glm::vec<N, float>> values;
        if (accessorIndex < 0) return values;
        const tinygltf::Accessor& accessor =
            accessorAt(accessorIndex, N == 2 ? TINYGLTF_TYPE_VEC2 : TINYGLTF_TYPE_VEC3);
        const size_t componentSize = tinygltf::GetComponentSizeInBytes(static_cast<uint32_t>(accessor.componentType));
        const bool isFloat = accessor.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT;
        if (!isFloat && !(accessor.normalized && (accessor.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                                                  accessor.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT)))
            fail("accessor " + std::to_string(accessorIndex) + " is neither float nor normalised unsigned");
        const float scale = componentSize == 1 ? 255.0f : 65535.0f;
        forEachElement(accessor, componentSize * N, [&](const unsigned char* element) {
            glm::vec<N, float> value;
            for (int k = 0; k < N; ++k) {
                const unsigned char* bytes = element + k * componentSize;
                if (isFloat)
                    std::memcpy(&value[k], bytes, sizeof(float));
                else
                    value[k] = static_cast<float>(componentSize == 1 ? bytes[0] : bytes[0] | bytes[1] << 8) / scale;
            }
            values.push_back(value);
        });
        return values;
    }

    std::vector<uint32_t> indices(int accessorIndex) const {
        const tinygltf::Accessor& accessor = accessorAt(accessorIndex, TINYGLTF_TYPE_SCALAR);
        const int size = tinygltf::GetComponentSizeInBytes(static_cast<uint32_t>(accessor.componentType));
        if (accessor.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
            accessor.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
            accessor.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
            fail("index accessor " + std::to_string(accessorIndex) + " is not unsigned");
        std::vector<uint32_t> values;
        forEachElement(accessor, static_cast<size_t>(size), [&](const unsigned char* bytes) {
            uint32_t value = 0;
            for (int k = 0; k < size; ++k) value |= static_cast<uint32_t>(bytes[k]) << (8 * k); // little-endian
            values.push_back(value);
        });
        return values;
    }

private:
    const tinygltf::Accessor& accessorAt(int index, int type) const {
        if (index < 0 || static_cast<size_t>(index) >= model.accessors.size())
            fail("accessor " + std::to_string(index) + " does not exist");
        const tinygltf::Accessor& accessor = model.accessors[static_cast<size_t>(index)];
        if (accessor.type != type) fail("accessor " + std::to_string(index) + " has the wrong type");
        if (accessor.sparse.isSparse) fail("sparse accessors are not supported");
        return accessor;
    }

    // Offsets, lengths, strides and counts come from the file and may be near
    // 2^64: every bound is checked by subtraction, never by a sum that wraps.
    template <typename Visit>
    void forEachElement(const tinygltf::Accessor& accessor, size_t elementSize, Visit visit) const {
        if (accessor.bufferView < 0 || static_cast<size_t>(accessor.bufferView) >= model.bufferViews.size())
            fail("an accessor has no buffer view");
        const tinygltf::BufferView& view = model.bufferViews[static_cast<size_t>(accessor.bufferView)];
        if (view.buffer < 0 || static_cast<size_t>(view.buffer) >= model.buffers.size())
            fail("a buffer view has no buffer");
        const std::vector<unsigned char>& data = model.buffers[static_cast<size_t>(view.buffer)].data;
        if (view.byteOffset > data.size() || view.byteLength > data.size() - view.byteOffset)
            fail("a buffer view reaches past its buffer");
        if (view.byteStride != 0 && view.byteStride < elementSize)
            fail("a buffer view's stride is shorter than the elements of its accessor");
        const size_t stride = view.byteStride != 0 ? view.byteStride : elementSize;
        if (accessor.count == 0) return;
        if (accessor.byteOffset > view.byteLength || view.byteLength - accessor.byteOffset < elementSize ||
            accessor.count - 1 > (view.byteLength - accessor.byteOffset - elementSize) / stride)
            fail("an accessor reaches past its buffer view");
        const unsigned char* first = data.data() + view.byteOffset + accessor.byteOffset;
        for (size_t i = 0; i < accessor.count; ++i) visit(first + i * stride);
    }
};

// tinygltf recurses once per nesting level of the JSON (100 000 nested
// arrays overflow the stack) and reads whatever a uri names (a folder ends in
// bad_alloc), so the document is looked at first: a size limit, the JSON's
// depth (glTF's own structure is six levels deep; extras get the rest) and
// every external uri a regular file.
constexpr size_t kMaxMeshFileBytes = size_t(1) << 30;
constexpr int kMaxJsonDepth = 64;

// The JSON of a .gltf, or the JSON chunk of a .glb (glTF 2.0 §4.4.3).
std::string documentJson(const std::filesystem::path& file, bool binary, const MeshFileReader& reader) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(file, ec)) reader.fail("is not a readable file");
    FileBytes read = readFileUpTo(file, kMaxMeshFileBytes);
    if (read.problem == FileProblem::TooLarge)
        reader.fail("is larger than " + std::to_string(kMaxMeshFileBytes >> 20) + " MiB");
    if (read.problem != FileProblem::None) reader.fail("cannot be read");
    std::string& bytes = read.bytes;
    if (!binary) return std::move(bytes);
    constexpr size_t kHeader = 12, kChunkHeader = 8;
    if (bytes.size() < kHeader + kChunkHeader) reader.fail("is too short for a .glb header");
    uint32_t jsonLength = 0;
    std::memcpy(&jsonLength, bytes.data() + kHeader, sizeof jsonLength);
    if (jsonLength > bytes.size() - kHeader - kChunkHeader) reader.fail("has a JSON chunk longer than the file");
    return bytes.substr(kHeader + kChunkHeader, jsonLength);
}

// A uri's %XX escapes as bytes (RFC 3986 §2.1), as tinygltf reads it.
std::string percentDecoded(const std::string& uri) {
    std::string out;
    for (size_t i = 0; i < uri.size(); ++i) {
        if (uri[i] == '%' && i + 2 < uri.size() && std::isxdigit(static_cast<unsigned char>(uri[i + 1])) &&
            std::isxdigit(static_cast<unsigned char>(uri[i + 2]))) {
            out += static_cast<char>(std::stoi(uri.substr(i + 1, 2), nullptr, 16));
            i += 2;
        } else {
            out += uri[i];
        }
    }
    return out;
}

void checkExternalUris(const nlohmann::json& document, const char* array, const std::filesystem::path& folder,
                       const MeshFileReader& reader) {
    const auto found = document.find(array);
    if (found == document.end() || !found->is_array()) return;
    for (size_t i = 0; i < found->size(); ++i) {
        const nlohmann::json& entry = (*found)[i];
        if (!entry.is_object() || !entry.contains("uri") || !entry["uri"].is_string()) continue;
        const std::string uri = entry["uri"].get<std::string>();
        if (uri.rfind("data:", 0) == 0) continue;
        const std::filesystem::path target = folder / percentDecoded(uri);
        std::error_code ec; // a name too long for the file system is no file either
        if (!std::filesystem::is_regular_file(target, ec))
            reader.fail(std::string(array) + "[" + std::to_string(i) + "] names '" + uri + "', which is not a file");
    }
}

void checkBeforeReading(const std::filesystem::path& file, bool binary, const MeshFileReader& reader) {
    const std::string json = documentJson(file, binary, reader);
    const auto limitDepth = [&](int depth, nlohmann::json::parse_event_t, nlohmann::json&) {
        if (depth > kMaxJsonDepth)
            reader.fail("nests its JSON deeper than " + std::to_string(kMaxJsonDepth) + " levels");
        return true;
    };
    const nlohmann::json document = nlohmann::json::parse(json, limitDepth, false);
    if (document.is_discarded() || !document.is_object()) return; // tinygltf reports the syntax error
    checkExternalUris(document, "buffers", file.parent_path(), reader);
    checkExternalUris(document, "images", file.parent_path(), reader);
}

int attribute(const tinygltf::Primitive& primitive, const char* name) {
    const auto found = primitive.attributes.find(name);
    return found == primitive.attributes.end() ? -1 : found->second;
}

} // namespace

SurfaceMesh loadSurfaceFile(const std::filesystem::path& file, const std::string& name) {
    tinygltf::TinyGLTF loader;
    tinygltf::Model model;
    std::string error;
    std::string warning;
    const bool binary = file.extension() == ".glb";
    const MeshFileReader reader{model, file};
    checkBeforeReading(file, binary, reader);
    bool loaded = false;
    try {
        loaded = binary ? loader.LoadBinaryFromFile(&model, &error, &warning, file.string())
                        : loader.LoadASCIIFromFile(&model, &error, &warning, file.string());
    } catch (const std::bad_alloc&) {
        reader.fail("asks for more memory than there is (a length in it is too large)");
    }
    if (!loaded) reader.fail(error.empty() ? "cannot be read" : error);
    if (model.meshes.empty()) reader.fail("has no mesh");

    SurfaceMesh mesh;
    mesh.name = name;
    bool allNormals = true;
    bool allUvs = true;
    for (const tinygltf::Primitive& primitive : model.meshes.front().primitives) {
        if (primitive.mode != -1 && primitive.mode != TINYGLTF_MODE_TRIANGLES) continue;
        const int positionAccessor = attribute(primitive, "POSITION");
        if (positionAccessor < 0) reader.fail("a primitive has no POSITION");
        const uint32_t base = static_cast<uint32_t>(mesh.positions.size());
        const std::vector<glm::vec3> positions = reader.vectors<3>(positionAccessor);
        const std::vector<glm::vec3> normals = reader.vectors<3>(attribute(primitive, "NORMAL"));
        const std::vector<glm::vec2> uvs = reader.vectors<2>(attribute(primitive, "TEXCOORD_0"));
        const size_t count = positions.size();
        mesh.positions.insert(mesh.positions.end(), positions.begin(), positions.end());
        allNormals = allNormals && normals.size() == count;
        allUvs = allUvs && uvs.size() == count;
        if (allNormals) mesh.normals.insert(mesh.normals.end(), normals.begin(), normals.end());
        if (allUvs) mesh.uvs.insert(mesh.uvs.end(), uvs.begin(), uvs.end());

        std::vector<uint32_t> indices;
        if (primitive.indices < 0)
            for (uint32_t i = 0; i < count; ++i) indices.push_back(i);
        else
            indices = reader.indices(primitive.indices);
        if (indices.size() % 3 != 0) reader.fail("a triangle list's index count is not a multiple of 3");
        for (uint32_t index : indices) {
            if (index >= count) reader.fail("an index points past the vertices");
            mesh.indices.push_back(base + index);
        }
    }
    if (mesh.indices.empty()) reader.fail("its first mesh has no triangles");
    if (!allNormals) mesh.normals.clear();
    if (!allUvs) mesh.uvs.clear();
    return mesh;
}

} // namespace lsys
