// A whole field as glTF and as a placements table, from the CPU-side field
// (no Vulkan here). docs/EXPORT.md "Whole fields".
#include "field_export.h"

#include "engine/scene/terrain.h"
#include "lsystem/common/output_file.h"
#include "lsystem/export/export_detail.h"
#include "lsystem/export/gltf_builder.h"
#include "lsystem/mesh/drawn_mesh.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace pf {
namespace {

using lsys::export_detail::GltfBuilder;
using lsys::export_detail::lowercaseExtension;

constexpr const char* kInstancing = "EXT_mesh_gpu_instancing";

// One material of the export: an albedo and a surface kind, as the renderer
// packs them into FieldVertex::albedo.
using MaterialKey = std::array<float, 4>;

const char* surfaceName(lsys::SurfaceKind kind) {
    if (kind == lsys::SurfaceKind::LeafCard) return "leaf";
    if (kind == lsys::SurfaceKind::Blade) return "blade";
    return "bark";
}

// The plant models' materials, the terrain's first, in the order they are met.
struct Materials {
    std::vector<lsys::Material> list;
    std::map<MaterialKey, uint32_t> index;

    uint32_t of(glm::vec3 albedo, lsys::SurfaceKind kind) {
        const MaterialKey key{albedo.x, albedo.y, albedo.z, float(kind)};
        const auto [it, added] = index.try_emplace(key, uint32_t(list.size()));
        if (added) {
            lsys::Material& m = list.emplace_back();
            m.name = std::string(surfaceName(kind)) + " " + std::to_string(list.size() - 1);
            m.albedo = albedo;
            m.twoSided = kind != lsys::SurfaceKind::Bark; // leaves and blades are seen from both sides
        }
        return it->second;
    }
};

glm::vec3 unitOr(glm::vec3 n, glm::vec3 fallback) {
    const float length = glm::length(n);
    return length > 0.0f && std::isfinite(length) ? n / length : fallback;
}

// What the export bakes a model with: the renderer's trunk ring sides, so
// bark matches the field's LOD0, and leaf cards as the leaf outline the
// renderer's shader cuts from them (the file has no texture to cut with),
// as `lsys export` bakes a plant.
lsys::DrawnOptions modelDrawnOptions() { return lsys::exportedDrawnOptions(lsys::DrawnOptions{}.trunkSides); }

// A model's LOD0 baked from its plant with modelDrawnOptions, scaled as the
// field's model is, split by material: (material, mesh) pairs. A vertex is
// written when a triangle first uses it, in the triangles' order.
std::vector<std::pair<uint32_t, lsys::TriangleMesh>> modelMeshes(const PlantModelAsset& plant, Materials& materials) {
    const lsys::PlantAsset& asset = plant.asset;
    const lsys::DrawnClasses drawn =
        lsys::drawnLod(asset, lsys::DrawnLod::Full, lsys::drawnScaleOf(asset), modelDrawnOptions());
    constexpr uint32_t kUnwritten = ~0u;
    std::map<uint32_t, lsys::TriangleMesh> parts;
    for (const lsys::DrawnMesh& mesh : drawn) {
        std::map<uint32_t, std::vector<uint32_t>> remaps; // per material: drawn vertex → mesh vertex
        for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
            const lsys::DrawnVertex& first = mesh.vertices[mesh.indices[t]];
            const uint32_t material = materials.of(asset.materials.at(first.material).albedo, first.kind);
            lsys::TriangleMesh& part = parts[material];
            std::vector<uint32_t>& remap = remaps.try_emplace(material, mesh.vertices.size(), kUnwritten).first->second;
            for (size_t c = 0; c < 3; ++c) {
                const uint32_t corner = mesh.indices[t + c];
                if (remap[corner] == kUnwritten) {
                    remap[corner] = part.vertexCount();
                    const lsys::DrawnVertex& v = mesh.vertices[corner];
                    part.positions.push_back(v.position * plant.scale);
                    part.normals.push_back(unitOr(v.normal, {0.0f, 1.0f, 0.0f}));
                    part.uvs.push_back(v.uv);
                }
                part.indices.push_back(remap[corner]);
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

// Bytes of a model's LOD0 as modelMeshes holds it: every index of the
// field's LOD0 may bring a vertex (a card's six over-count its quad), each
// leaf card its outline (every drawable surface is a card at LOD0). The
// written meshes hold a vertex in 32 bytes; the bake, one model at a time,
// in a DrawnVertex with its remap entry.
struct ModelBytes {
    uint64_t written = 0, baked = 0;
};
ModelBytes modelBytes(const PlantModelInfo& model, const PlantModelAsset& plant) {
    uint64_t indices = 0, cards = 0;
    for (const MeshRange& range : model.meshes[LOD_FULL]) indices = lsys::bytesPlus(indices, range.indexCount);
    for (const lsys::Primitive& p : plant.asset.primitives)
        cards += p.kind == lsys::PrimitiveKind::Surface && lsys::isDrawable(p);
    const lsys::MeshSize outline = lsys::leafOutlineSize();
    const uint64_t vertices = lsys::bytesPlus(indices, lsys::bytesTimes(cards, outline.vertices));
    const uint64_t indexBytes = lsys::bytesTimes(lsys::bytesPlus(indices, lsys::bytesTimes(cards, outline.indices)), 4);
    return {lsys::bytesPlus(lsys::bytesTimes(vertices, 32), indexBytes),
            lsys::bytesPlus(lsys::bytesTimes(vertices, sizeof(lsys::DrawnVertex) + 4), indexBytes)};
}

// What exportField holds at once, from counts known before any mesh is built:
// every model's meshes (modelBytes) and the largest bake, the terrain's
// vertices and indices, the instance attributes (40 bytes a plant) or the
// plain nodes; all of it about three times over (the meshes, the glTF buffer
// and its copy in the file's encoding, base64 for .gltf).
uint64_t exportBytes(const FieldContent& content, const FieldExportOptions& options, bool binary) {
    const PlantModelPool& pool = content.models;
    uint64_t data = 0, largestBake = 0;
    for (size_t m = 0; m < pool.models.size(); ++m) {
        const ModelBytes bytes = modelBytes(pool.models[m], pool.assets[m]);
        data = lsys::bytesPlus(data, bytes.written);
        largestBake = std::max(largestBake, bytes.baked);
    }
    const uint64_t resolution = content.terrain.resolution;
    data = lsys::bytesPlus(data, largestBake);
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
        const PlantModelPool& pool = content.models;
        if (pool.assets.size() != pool.models.size())
            throw std::invalid_argument("the field was built without its models' plants (ModelAssets::Keep)");
        lsys::need(options.memory, "export", exportBytes(content, options, extension == ".glb"));
        lsys::OutputFile file(path); // checks the path before the work

        Materials materials;
        materials.list.push_back({"terrain", content.scene.terrain.albedo, false});
        std::vector<std::vector<std::pair<uint32_t, lsys::TriangleMesh>>> parts;
        for (const PlantModelAsset& plant : pool.assets) parts.push_back(modelMeshes(plant, materials));

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
