// A whole field as glTF and as a placements table, from the CPU-side field
// (no Vulkan here). docs/EXPORT.md "Whole fields".
#include "field_export.h"

#include "engine/scene/terrain.h"
#include "lsystem/drawn_mesh.h"
#include "lsystem/export_detail.h"
#include "lsystem/gltf_builder.h"
#include "lsystem/output_file.h"

#include <glm/geometric.hpp>

#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

namespace pf {
namespace {

using lsys::export_detail::GltfBuilder;
using lsys::export_detail::lowercaseExtension;

constexpr const char* kInstancing = "EXT_mesh_gpu_instancing";

// One material of the export: a vertex's albedo and surface kind (FieldVertex::albedo).
using MaterialKey = std::array<float, 4>;

const char* surfaceName(float kind) {
    if (kind == SURFACE_LEAF) return "leaf";
    if (kind == SURFACE_BLADE) return "blade";
    return "bark";
}

// The plant models' materials, the terrain's first, in the order they are met.
struct Materials {
    std::vector<lsys::Material> list;
    std::map<MaterialKey, uint32_t> index;

    uint32_t of(const gpu::FieldVertex& v) {
        const MaterialKey key{v.albedo.x, v.albedo.y, v.albedo.z, v.albedo.w};
        const auto [it, added] = index.try_emplace(key, uint32_t(list.size()));
        if (added) {
            lsys::Material& m = list.emplace_back();
            m.name = std::string(surfaceName(v.albedo.w)) + " " + std::to_string(list.size() - 1);
            m.albedo = {v.albedo.x, v.albedo.y, v.albedo.z};
            m.twoSided = v.albedo.w != SURFACE_BARK; // leaf cards and blades are seen from both sides
        }
        return it->second;
    }
};

glm::vec3 unitOr(glm::vec3 n, glm::vec3 fallback) {
    const float length = glm::length(n);
    return length > 0.0f && std::isfinite(length) ? n / length : fallback;
}

glm::vec3 positionOf(const gpu::FieldVertex& v) { return glm::vec3(v.position); }

// Whether the triangle is the first of a leaf card's two: a card is the quad
// a b c d (uv (0,0) (1,0) (1,1) (0,1), in that vertex order) drawn as a b c
// and a c d (lsystem/drawn_mesh.cpp bakeLeafCard).
bool isLeafCardStart(const PlantModelPool& pool, const MeshRange& range, const uint32_t* corners) {
    const gpu::FieldVertex& a = pool.vertices[range.vertexOffset + corners[0]];
    const gpu::FieldVertex& b = pool.vertices[range.vertexOffset + corners[1]];
    return a.albedo.w == SURFACE_LEAF && a.position.w == 0.0f && a.normal.w == 0.0f && b.position.w == 1.0f &&
           b.normal.w == 0.0f;
}

// A model's LOD0 meshes (bark and foliage) split by material: (material,
// mesh) pairs. Leaf cards become the mesh of the leaf outline the renderer's
// shader cuts from them (the file has no texture to cut with).
std::vector<std::pair<uint32_t, lsys::TriangleMesh>> modelMeshes(const PlantModelPool& pool,
                                                                 const PlantModelInfo& model, Materials& materials) {
    std::map<uint32_t, lsys::TriangleMesh> parts;
    std::map<uint32_t, std::unordered_map<uint32_t, uint32_t>> remaps; // per material: pool vertex → mesh vertex
    for (const MeshRange& range : model.meshes[LOD_FULL]) {
        for (uint32_t t = 0; t + 2 < range.indexCount; t += 3) {
            const uint32_t* corners = &pool.indices[range.firstIndex + t];
            const gpu::FieldVertex& first = pool.vertices[range.vertexOffset + corners[0]];
            const uint32_t material = materials.of(first);
            lsys::TriangleMesh& mesh = parts[material];
            if (first.albedo.w == SURFACE_LEAF) {
                if (isLeafCardStart(pool, range, corners)) {
                    const glm::vec3 a = positionOf(first);
                    const glm::vec3 b = positionOf(pool.vertices[range.vertexOffset + corners[1]]);
                    const glm::vec3 d = positionOf(pool.vertices[range.vertexOffset + corners[2] + 1]); // after c
                    lsys::appendLeafOutline(mesh, a, b - a, d - a, unitOr(glm::vec3(first.normal), {0, 1, 0}));
                }
                continue;
            }
            std::unordered_map<uint32_t, uint32_t>& remap = remaps[material];
            for (int c = 0; c < 3; ++c) {
                const uint32_t vertex = range.vertexOffset + corners[c];
                const auto [it, added] = remap.try_emplace(vertex, mesh.vertexCount());
                if (added) {
                    const gpu::FieldVertex& v = pool.vertices[vertex];
                    mesh.positions.push_back(positionOf(v));
                    mesh.normals.push_back(unitOr({v.normal.x, v.normal.y, v.normal.z}, {0.0f, 1.0f, 0.0f}));
                    mesh.uvs.emplace_back(v.position.w, v.normal.w);
                }
                mesh.indices.push_back(it->second);
            }
        }
    }
    std::vector<std::pair<uint32_t, lsys::TriangleMesh>> out;
    for (auto& [material, mesh] : parts) out.emplace_back(material, std::move(mesh));
    return out;
}

lsys::TriangleMesh terrainMesh(const Heightfield& terrain) {
    TerrainMesh source = makeTerrainMesh(terrain);
    lsys::TriangleMesh mesh;
    mesh.positions = std::move(source.positions);
    mesh.normals = std::move(source.normals);
    mesh.indices = std::move(source.indices);
    mesh.uvs.reserve(mesh.positions.size());
    for (const glm::vec3& p : mesh.positions)
        mesh.uvs.emplace_back(p.x / terrain.size + 0.5f, p.z / terrain.size + 0.5f);
    return mesh;
}

// An accessor of `values` in a buffer view of its own, without a target (instance attributes are not vertex data).
template <typename T>
int addInstanceAccessor(tinygltf::Model& model, const std::vector<T>& values, int type) {
    std::vector<unsigned char>& data = model.buffers[0].data;
    tinygltf::BufferView& view = model.bufferViews.emplace_back();
    view.buffer = 0;
    view.byteOffset = data.size(); // every view holds 4-byte floats, so every offset stays aligned
    view.byteLength = values.size() * sizeof(T);
    data.resize(data.size() + view.byteLength);
    std::memcpy(data.data() + view.byteOffset, values.data(), view.byteLength);
    tinygltf::Accessor& accessor = model.accessors.emplace_back();
    accessor.bufferView = int(model.bufferViews.size() - 1);
    accessor.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
    accessor.type = type;
    accessor.count = values.size();
    return int(model.accessors.size() - 1);
}

void appendFloat(std::string& out, float value) {
    char buffer[32];
    const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, value);
    out.append(buffer, ec == std::errc() ? end : buffer);
}

// RFC 4180: a field with a comma, a quote or a line break is quoted, its quotes doubled.
std::string csvField(const std::string& text) {
    if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
    std::string quoted = "\"";
    for (char c : text) {
        if (c == '"') quoted += '"';
        quoted += c;
    }
    return quoted + '"';
}

std::string jsonString(const std::string& text) {
    std::string out = "\"";
    for (unsigned char c : text) {
        if (c == '"' || c == '\\') {
            out += '\\';
            out += char(c);
        } else if (c < 0x20) {
            char escape[8];
            std::snprintf(escape, sizeof escape, "\\u%04x", c);
            out += escape;
        } else {
            out += char(c);
        }
    }
    return out + '"';
}

// What exportField holds at once, from counts known before any mesh is built:
// every LOD0 index may bring a vertex (32 bytes written, more while built; a
// leaf card's six bring its outline, below),
// the terrain's vertices and indices, the instance attributes (40 bytes a
// plant) or the plain nodes; all of it about three times over (the meshes,
// the glTF buffer and its copy in the file's encoding, base64 for .gltf).
uint64_t exportBytes(const FieldContent& content, const FieldExportOptions& options, bool binary) {
    const PlantModelPool& pool = content.models;
    uint64_t indices = 0, leafCards = 0;
    for (const PlantModelInfo& model : pool.models)
        for (const MeshRange& range : model.meshes[LOD_FULL]) {
            indices = lsys::bytesPlus(indices, range.indexCount);
            for (uint32_t t = 0; t + 2 < range.indexCount; t += 3)
                leafCards += isLeafCardStart(pool, range, &pool.indices[range.firstIndex + t]);
        }
    const lsys::LeafOutline& outline = lsys::leafOutline();
    const uint64_t outlineBytes = outline.uvs.size() * (32 + 64) + outline.indices.size() * 4;
    const uint64_t resolution = content.terrain.resolution;
    uint64_t data = lsys::bytesTimes(indices, 4 + 64);
    data = lsys::bytesPlus(data, lsys::bytesTimes(leafCards, outlineBytes));
    data = lsys::bytesPlus(data, lsys::bytesTimes(resolution * resolution, 32 + 24));
    data = lsys::bytesPlus(data, lsys::bytesTimes(resolution * resolution, 6 * 4));
    data = lsys::bytesPlus(data, lsys::bytesTimes(content.plants.size(), 40));
    uint64_t bytes = lsys::bytesTimes(data, binary ? 3 : 4);
    const uint64_t nodes = options.gpuInstancing ? content.models.models.size() : content.plants.size();
    return lsys::bytesPlus(bytes, lsys::bytesTimes(nodes, lsys::export_detail::kGltfNodeBytes));
}

} // namespace

glm::quat yawRotation(float yaw) { return glm::angleAxis(yaw, glm::vec3(0.0f, 1.0f, 0.0f)); }

FieldExportSummary exportField(const FieldContent& content, const std::filesystem::path& path,
                               const FieldExportOptions& options) {
    try {
        const std::string extension = lowercaseExtension(path);
        if (extension != ".glb" && extension != ".gltf")
            throw std::runtime_error("unknown extension '" + path.extension().string() + "' (expected .glb or .gltf)");
        lsys::need(options.memory, "export", exportBytes(content, options, extension == ".glb"));
        lsys::OutputFile file(path); // checks the path before the work

        const PlantModelPool& pool = content.models;
        Materials materials;
        materials.list.push_back({"terrain", content.scene.terrain.albedo, false});
        std::vector<std::vector<std::pair<uint32_t, lsys::TriangleMesh>>> parts;
        for (const PlantModelInfo& model : pool.models) parts.push_back(modelMeshes(pool, model, materials));

        GltfBuilder builder(materials.list);
        tinygltf::Model& gltf = builder.model;
        gltf.asset.generator = "plantfield field exporter";
        gltf.nodes[GltfBuilder::kRoot].name = "field";
        FieldExportSummary summary;
        summary.materials = materials.list.size();

        const int terrain = builder.addMesh(terrainMesh(content.terrain), 0, "terrain");
        if (terrain >= 0) {
            builder.addNode("terrain", GltfBuilder::kRoot, lsys::Frame{}, terrain);
            ++summary.meshes;
        }
        std::vector<int> meshOf(pool.models.size(), -1);
        for (size_t m = 0; m < pool.models.size(); ++m) {
            std::vector<lsys::TriangleMesh> byMaterial(materials.list.size());
            for (auto& [material, mesh] : parts[m]) byMaterial[material] = std::move(mesh);
            parts[m].clear();
            meshOf[m] = builder.addMesh(byMaterial, pool.models[m].name);
            if (meshOf[m] >= 0) ++summary.meshes;
        }

        // The plants of each model, in the field's order.
        std::vector<std::vector<const PlantInstance*>> plantsOf(pool.models.size());
        for (const PlantInstance& plant : content.plants)
            plantsOf[pool.modelOf(plant.species, plant.variant)].push_back(&plant);

        for (size_t m = 0; m < pool.models.size(); ++m) {
            const std::vector<const PlantInstance*>& plants = plantsOf[m];
            if (meshOf[m] < 0 || plants.empty()) continue; // nothing to draw, or never planted
            summary.plants += plants.size();
            const std::string& name = pool.models[m].name;
            if (options.gpuInstancing) {
                std::vector<glm::vec3> translations, scales;
                std::vector<glm::vec4> rotations;
                for (const PlantInstance* plant : plants) {
                    translations.push_back(plant->position);
                    const glm::quat q = yawRotation(plant->rotation);
                    rotations.emplace_back(q.x, q.y, q.z, q.w);
                    scales.emplace_back(plant->scale);
                }
                tinygltf::Value::Object attributes;
                attributes["TRANSLATION"] =
                    tinygltf::Value(addInstanceAccessor(gltf, translations, TINYGLTF_TYPE_VEC3));
                attributes["ROTATION"] = tinygltf::Value(addInstanceAccessor(gltf, rotations, TINYGLTF_TYPE_VEC4));
                attributes["SCALE"] = tinygltf::Value(addInstanceAccessor(gltf, scales, TINYGLTF_TYPE_VEC3));
                tinygltf::Value::Object extension;
                extension["attributes"] = tinygltf::Value(std::move(attributes));
                const int node = builder.addNode(name, GltfBuilder::kRoot, lsys::Frame{}, meshOf[m]);
                gltf.nodes[size_t(node)].extensions[kInstancing] = tinygltf::Value(std::move(extension));
            } else {
                const int group = builder.addNode(name, GltfBuilder::kRoot, lsys::Frame{});
                for (size_t i = 0; i < plants.size(); ++i) {
                    const PlantInstance& plant = *plants[i];
                    const int node =
                        builder.addNode(name + "." + std::to_string(i), group,
                                        lsys::Frame{plant.position, yawRotation(plant.rotation)}, meshOf[m]);
                    if (plant.scale != 1.0f) gltf.nodes[size_t(node)].scale = {plant.scale, plant.scale, plant.scale};
                }
            }
        }
        if (options.gpuInstancing && summary.plants > 0) gltf.extensionsUsed.push_back(kInstancing);
        summary.nodes = gltf.nodes.size();
        builder.write(file.stream(), extension == ".glb");
        file.commit();
        return summary;
    } catch (...) {
        lsys::export_detail::rethrowNaming(path);
    }
}

void exportPlacements(const FieldContent& content, const std::filesystem::path& path) {
    try {
        const std::string extension = lowercaseExtension(path);
        const bool json = extension == ".json";
        if (!json && extension != ".csv")
            throw std::runtime_error("unknown extension '" + path.extension().string() + "' (expected .csv or .json)");
        lsys::OutputFile file(path);
        const PlantModelPool& pool = content.models;
        std::vector<std::string> species, models;
        for (const Species& s : content.scene.species) species.push_back(json ? jsonString(s.name) : csvField(s.name));
        for (const PlantModelInfo& m : pool.models) models.push_back(json ? jsonString(m.name) : csvField(m.name));

        static constexpr std::array<const char*, 8> kNumbers{"x", "y", "z", "qx", "qy", "qz", "qw", "scale"};
        std::string out = json ? "[" : "species,model,x,y,z,qx,qy,qz,qw,scale\n";
        for (size_t i = 0; i < content.plants.size(); ++i) {
            const PlantInstance& plant = content.plants[i];
            const glm::quat q = yawRotation(plant.rotation);
            const std::array<float, 8> values{plant.position.x, plant.position.y, plant.position.z, q.x, q.y, q.z, q.w,
                                              plant.scale};
            const std::string& model = models[pool.modelOf(plant.species, plant.variant)];
            if (json) {
                out += i == 0 ? "\n  {\"species\": " : ",\n  {\"species\": ";
                out += species[plant.species];
                out += ", \"model\": ";
                out += model;
                for (size_t k = 0; k < values.size(); ++k) {
                    out += ", \"";
                    out += kNumbers[k];
                    out += "\": ";
                    appendFloat(out, values[k]);
                }
                out += '}';
            } else {
                out += species[plant.species];
                out += ',';
                out += model;
                for (float value : values) {
                    out += ',';
                    appendFloat(out, value);
                }
                out += '\n';
            }
            if (out.size() > (1u << 20)) {
                file.stream() << out;
                out.clear();
            }
        }
        if (json) out += content.plants.empty() ? "]\n" : "\n]\n";
        file.stream() << out;
        file.commit();
    } catch (...) {
        lsys::export_detail::rethrowNaming(path);
    }
}

} // namespace pf
