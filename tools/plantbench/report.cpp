#include "report.h"

#include "lsystem/common/memory_budget.h"
#include "lsystem/common/output_file.h"

#include "gpu_memory.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <ostream>
#include <sstream>
#include <stdexcept>

namespace pf {

std::optional<double> naiveRatio(const CountResult& r) {
    if (!r.naive || r.driven.frameMs.median <= 0.0) return std::nullopt;
    return r.naive->frameMs.median / r.driven.frameMs.median;
}

namespace {

std::string fixed(double value, int decimals) {
    char text[32];
    std::snprintf(text, sizeof(text), "%.*f", decimals, value);
    return text;
}

std::string cell(const std::optional<double>& value, int decimals) { return value ? fixed(*value, decimals) : "-"; }

std::optional<double> medianOf(const std::optional<Spread>& s) {
    return s ? std::optional<double>(s->median) : std::nullopt;
}

std::optional<double> p95Of(const std::optional<Spread>& s) { return s ? std::optional<double>(s->p95) : std::nullopt; }

nlohmann::json spreadJson(const std::optional<Spread>& s) {
    if (!s) return nullptr;
    return {{"median", s->median}, {"p95", s->p95}};
}

nlohmann::json gpuJson(const PathTimes& t) {
    nlohmann::json j = nlohmann::json::object();
    for (size_t p = 0; p < kPassCount; ++p) j[kBenchPasses[p]] = spreadJson(t.gpuMs[p]);
    return j;
}

// What one GPU-driven measurement saw: times, plants per LOD, culled, triangles, draws.
nlohmann::json frameJson(const PathTimes& t, const FieldFrameStats& stats) {
    nlohmann::json j;
    j["frame_ms"] = spreadJson(t.frameMs);
    j["cpu_ms"] = spreadJson(t.cpuMs);
    j["process_cpu_ms"] = spreadJson(t.processCpuMs);
    j["gpu_ms"] = gpuJson(t);
    j["shadow_cache_renders"] = t.shadowCacheRenders;
    j["plants_per_lod"] = nlohmann::json::object();
    for (uint32_t lod = 0; lod < LOD_COUNT; ++lod) j["plants_per_lod"][kLodNames[lod]] = stats.plantsPerLod[lod];
    j["culled"] = stats.culled();
    j["occluded"] = stats.occluded;
    j["canopy_plants"] = stats.clusterFarPlants;
    j["triangles"] = stats.triangles;
    j["draws"] = nlohmann::json::object();
    for (uint32_t c = 0; c < DRAW_CLASS_COUNT; ++c) j["draws"][kDrawClassNames[c]] = stats.draws[c];
    return j;
}

nlohmann::json pathJson(const CountResult& r) {
    if (r.alongPath.empty()) return nullptr;
    nlohmann::json path = nlohmann::json::array();
    for (const CameraTimeResult& t : r.alongPath) {
        nlohmann::json j = frameJson(t.driven, t.stats);
        j["time"] = t.time;
        path.push_back(j);
    }
    return path;
}

nlohmann::json countJson(const CountResult& r) {
    nlohmann::json j = frameJson(r.driven, r.stats);
    j["count"] = r.count;
    j["instances"] = r.stats.instances;
    j["time"] = r.time;
    j["path"] = pathJson(r);
    j["terrain_size_m"] = r.terrainSize;
    j["placement_note"] = r.placementNote.empty() ? nlohmann::json(nullptr) : nlohmann::json(r.placementNote);
    j["joints_simulated"] = r.jointsSimulated;
    j["gpu_memory_bytes"] = r.gpuMemoryBytes;
    j["renderer_bytes"] = r.rendererBytes;
    j["build_s"] = r.buildSeconds;
    if (r.naive)
        j["naive"] = {{"frame_ms", spreadJson(r.naive->frameMs)},
                      {"cpu_ms", spreadJson(r.naive->cpuMs)},
                      {"gpu_ms", gpuJson(*r.naive)},
                      {"triangles", r.naiveTriangles}};
    else
        j["naive"] = nullptr;
    const std::optional<double> ratio = naiveRatio(r);
    j["ratio"] = ratio ? nlohmann::json(*ratio) : nlohmann::json(nullptr);
    j["note"] = r.note.empty() ? nlohmann::json(nullptr) : nlohmann::json(r.note);
    return j;
}

// Columns right-aligned to their widest cell, two spaces apart.
void printTable(std::ostream& out, const std::vector<std::string>& headers,
                const std::vector<std::vector<std::string>>& rows) {
    std::vector<size_t> widths(headers.size());
    for (size_t c = 0; c < headers.size(); ++c) {
        widths[c] = headers[c].size();
        for (const auto& row : rows) widths[c] = std::max(widths[c], row[c].size());
    }
    auto printRow = [&](const std::vector<std::string>& row) {
        for (size_t c = 0; c < row.size(); ++c)
            out << (c ? "  " : "") << std::string(widths[c] - row[c].size(), ' ') << row[c];
        out << "\n";
    };
    printRow(headers);
    for (const auto& row : rows) printRow(row);
}

// With --path: each count's median frame ms at every time, the worst marked.
void printPathTable(std::ostream& out, const SweepResult& result) {
    const std::vector<CameraTimeResult>& first = result.counts.front().alongPath;
    std::vector<std::string> headers = {"count"};
    for (const CameraTimeResult& t : first) headers.push_back("t=" + fixed(t.time, 1));
    headers.push_back("worst ms");
    headers.push_back("at t");
    std::vector<std::vector<std::string>> rows;
    for (const CountResult& r : result.counts) {
        std::vector<std::string> row = {std::to_string(r.count)};
        const size_t slowest = slowestTime(r.alongPath);
        for (size_t i = 0; i < r.alongPath.size(); ++i)
            row.push_back(fixed(r.alongPath[i].driven.frameMs.median, 2) + (i == slowest ? "*" : ""));
        row.push_back(fixed(r.driven.frameMs.median, 2));
        row.push_back(fixed(r.time, 1));
        rows.push_back(row);
    }
    out << "frame ms (median) along the camera path, * the worst:\n";
    printTable(out, headers, rows);
}

} // namespace

void printSummaryTable(std::ostream& out, const PlantbenchOptions& o, const SweepResult& result) {
    std::vector<std::string> headers = {"count", "frame ms", "p95", "cpu ms", "process ms"};
    if (o.pathTimes) headers.push_back("at t");
    for (const char* pass : kBenchPasses) headers.push_back(std::string(pass) + " ms");
    for (const char* lod : kLodNames) headers.push_back(lod);
    for (const char* h : {"occluded", "triangles", "joints", "memory", "terrain m", "naive ms", "ratio"})
        headers.push_back(h);

    std::vector<std::vector<std::string>> rows;
    for (const CountResult& r : result.counts) {
        std::vector<std::string> row = {std::to_string(r.count), fixed(r.driven.frameMs.median, 2),
                                        fixed(r.driven.frameMs.p95, 2), fixed(r.driven.cpuMs.median, 2),
                                        fixed(r.driven.processCpuMs.median, 2)};
        if (o.pathTimes) row.push_back(fixed(r.time, 1));
        for (const std::optional<Spread>& pass : r.driven.gpuMs) row.push_back(cell(medianOf(pass), 3));
        for (uint32_t plants : r.stats.plantsPerLod) row.push_back(std::to_string(plants));
        row.push_back(std::to_string(r.stats.occluded));
        row.push_back(std::to_string(r.stats.triangles));
        row.push_back(std::to_string(r.jointsSimulated));
        row.push_back(lsys::formatBytes(r.gpuMemoryBytes));
        row.push_back(fixed(r.terrainSize, 0));
        row.push_back(r.naive ? fixed(r.naive->frameMs.median, 2) : "-");
        row.push_back(cell(naiveRatio(r), 1));
        rows.push_back(row);
    }
    out << "plantbench: " << result.scenePath << " on " << result.device << ", " << o.size.width << "x" << o.size.height
        << ", " << antialiasingText(o.antialiasing) << ", shadows " << sunShadowsName(o.shadows)
        << ", occlusion culling " << (o.occlusionCulling ? "on" : "off") << ", median of " << o.frames
        << " frames after " << o.warmup << " warm-up";
    if (o.pathTimes) out << ", the worst of " << *o.pathTimes << " times along the camera path";
    if (o.flyFps) out << ", the camera flying at " << fixed(*o.flyFps, 1) << " frames a second";
    out << (o.densify ? ", counts densified on the scene's terrain" : ", counts at the scene's densities") << "\n";
    printTable(out, headers, rows);
    out << "frame ms, p95: wall time per frame (median, 95th percentile); cpu ms: host time to record it; "
        << "process ms: CPU time of all the process's threads per frame (a CPU device's work); "
        << (o.pathTimes ? "at t: the camera time of the worst frame; " : "")
        << "pass columns: GPU ms (median), capture: copying the image to the host; joints: simulated; memory: "
        << result.memorySource << "; terrain m: side of the terrain; ratio: naive frame ms / GPU-driven frame ms\n";
    if (o.pathTimes && !result.counts.empty()) printPathTable(out, result);
    for (const CountResult& r : result.counts) {
        if (!r.placementNote.empty()) out << r.count << " plants: " << r.placementNote << "\n";
        if (!r.note.empty()) out << r.count << " plants: " << r.note << "\n";
    }
}

nlohmann::json sweepJson(const PlantbenchOptions& o, const SweepResult& result) {
    nlohmann::json j;
    j["scene"] = result.scenePath;
    j["device"] = result.device;
    j["size"] = {o.size.width, o.size.height};
    j["antialiasing"] = antialiasMethodName(o.antialiasing.method);
    j["samples"] = colorPassSamples(o.antialiasing);
    j["shadows"] = sunShadowsName(o.shadows);
    j["occlusion_culling"] = o.occlusionCulling;
    j["time"] = o.pathTimes ? nlohmann::json(nullptr) : nlohmann::json(o.time);
    j["path"] = o.pathTimes ? nlohmann::json(*o.pathTimes) : nlohmann::json(nullptr);
    j["fly_fps"] = o.flyFps ? nlohmann::json(*o.flyFps) : nlohmann::json(nullptr);
    j["count_mode"] = o.densify ? "densify" : "natural";
    j["frames"] = o.frames;
    j["warmup"] = o.warmup;
    j["memory_source"] = result.memorySource;
    j["results"] = nlohmann::json::array();
    for (const CountResult& r : result.counts) j["results"].push_back(countJson(r));
    return j;
}

std::string sweepCsv(const PlantbenchOptions& o, const SweepResult& result) {
    std::ostringstream csv;
    csv << "count,instances,frame_ms_median,frame_ms_p95,cpu_ms_median,cpu_ms_p95,process_cpu_ms_median,"
           "process_cpu_ms_p95";
    for (const char* pass : kBenchPasses) csv << ",gpu_" << pass << "_ms_median,gpu_" << pass << "_ms_p95";
    csv << ",plants_full,plants_reduced,plants_impostor,culled,triangles,joints_simulated,draws_bark,draws_foliage,"
           "draws_impostor"
           ",gpu_memory_bytes,naive_frame_ms_median,naive_frame_ms_p95,naive_triangles,ratio,terrain_size_m,time";
    for (uint32_t i = 1; i <= o.pathTimes.value_or(0); ++i)
        csv << ",path_time_" << i << ",path_frame_ms_median_" << i << ",path_frame_ms_p95_" << i;
    csv << "\n";
    auto ms = [](const std::optional<double>& v) { return v ? fixed(*v, 4) : std::string(); };
    for (const CountResult& r : result.counts) {
        csv << r.count << "," << r.stats.instances << "," << ms(r.driven.frameMs.median) << ","
            << ms(r.driven.frameMs.p95) << "," << ms(r.driven.cpuMs.median) << "," << ms(r.driven.cpuMs.p95) << ","
            << ms(r.driven.processCpuMs.median) << "," << ms(r.driven.processCpuMs.p95);
        for (const std::optional<Spread>& pass : r.driven.gpuMs)
            csv << "," << ms(medianOf(pass)) << "," << ms(p95Of(pass));
        for (uint32_t plants : r.stats.plantsPerLod) csv << "," << plants;
        csv << "," << r.stats.culled() << "," << r.stats.triangles << "," << r.jointsSimulated;
        for (uint32_t draws : r.stats.draws) csv << "," << draws;
        csv << "," << r.gpuMemoryBytes;
        if (r.naive)
            csv << "," << ms(r.naive->frameMs.median) << "," << ms(r.naive->frameMs.p95) << "," << r.naiveTriangles;
        else
            csv << ",,,";
        csv << "," << ms(naiveRatio(r)) << "," << fixed(r.terrainSize, 1) << "," << fixed(r.time, 4);
        for (const CameraTimeResult& t : r.alongPath)
            csv << "," << fixed(t.time, 4) << "," << ms(t.driven.frameMs.median) << "," << ms(t.driven.frameMs.p95);
        csv << "\n";
    }
    return csv.str();
}

void writeTextFile(const std::string& path, const std::string& text) {
    lsys::OutputFile file(path);
    file.stream() << text;
    file.commit();
}

} // namespace pf
