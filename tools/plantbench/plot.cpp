#include "plot.h"

#include "lsystem/common/output_file.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string_view>

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>

extern char** environ;

namespace pf {
namespace {

namespace fs = std::filesystem;

// A gnuplot single-quoted string: quotes are doubled, nothing else is special.
std::string quoted(const std::string& text) {
    std::string out = "'";
    for (char c : text) out += c == '\'' ? std::string("''") : std::string(1, c);
    return out + "'";
}

// Missing and non-positive values are NaN: gnuplot leaves them out of log axes.
std::string value(const std::optional<double>& v) {
    if (!v || *v <= 0.0) return "NaN";
    char text[32];
    std::snprintf(text, sizeof(text), "%.6g", *v);
    return text;
}

// Columns: 1 plants, 2 frame wall ms, 3 naive frame wall ms, then one per kBenchPasses entry.
std::string dataFile(const SweepResult& result) {
    std::ostringstream data;
    data << "# plants frame_ms naive_frame_ms";
    for (const char* pass : kBenchPasses) data << " " << pass << "_ms";
    data << "\n";
    for (const CountResult& r : result.counts) {
        data << r.count << " " << value(r.driven.frameMs.median) << " "
             << value(r.naive ? std::optional(r.naive->frameMs.median) : std::nullopt);
        for (const std::optional<Spread>& pass : r.driven.gpuMs)
            data << " " << value(pass ? std::optional(pass->median) : std::nullopt);
        data << "\n";
    }
    return data.str();
}

bool hasNaive(const SweepResult& result) {
    for (const CountResult& r : result.counts)
        if (r.naive) return true;
    return false;
}

// One panel: `perThousand` divides every value by thousands of plants.
std::string plotCommand(const std::string& data, bool perThousand, bool naive) {
    auto y = [&](int column) {
        return perThousand ? "($" + std::to_string(column) + "*1000/$1)" : std::to_string(column);
    };
    std::ostringstream plot;
    plot << "plot " << quoted(data) << " using 1:" << y(2)
         << " with linespoints lw 3 lc rgb '#000000' pt 7 ps 1.2 title 'frame wall time (CPU clock)'";
    if (naive)
        plot << ", '' using 1:" << y(3)
             << " with linespoints lw 2 dt 2 lc rgb '#000000' pt 6 ps 1.2 title 'naive frame wall time'";
    // Top-level passes solid with filled points, the draw scopes inside
    // "colour" thin and dotted with open ones; a colour of its own each.
    const char* colors[] = {"#17becf", "#1f77b4", "#ff7f0e", "#d62728", "#2ca02c",
                            "#9467bd", "#8c564b", "#e377c2", "#bcbd22", "#7f7f7f"};
    const int filledPoints[] = {5, 7, 9, 11, 13, 15};
    const int openPoints[] = {4, 6, 8, 10, 12, 14};
    size_t topLevel = 0, nestedCount = 0;
    for (size_t p = 0; p < kPassCount; ++p) {
        const bool nested = nestedInColor(p);
        const int point = nested ? openPoints[nestedCount++ % std::size(openPoints)]
                                 : filledPoints[topLevel++ % std::size(filledPoints)];
        const bool capture = kBenchPasses[p] == std::string_view(kCapturePass);
        const char* label = nested ? " (inside colour)" : capture ? " (GPU, image to host)" : " (GPU)";
        plot << ", '' using 1:" << y(4 + int(p)) << " with linespoints" << (nested ? " lw 1.5 dt 3" : " lw 2") << " pt "
             << point << " lc rgb '" << colors[p % std::size(colors)] << "' title '" << kBenchPasses[p] << label << "'";
    }
    return plot.str() + "\n";
}

// A little room left and right of the measured counts, each with a tic.
std::string xAxis(const SweepResult& result) {
    uint64_t low = result.counts.front().count, high = low;
    std::ostringstream tics;
    for (const CountResult& r : result.counts) {
        low = std::min(low, r.count);
        high = std::max(high, r.count);
        tics << (tics.tellp() > 0 ? ", " : "") << r.count;
    }
    std::ostringstream axis;
    axis << "set xrange [" << double(low) / 1.5 << ":" << double(high) * 1.5 << "]\n"
         << "set xtics add (" << tics.str() << ")\n";
    return axis.str();
}

std::string script(const PlantbenchOptions& o, const SweepResult& result, const std::string& data,
                   const std::string& terminal, const std::string& output) {
    const std::string scene = fs::path(result.scenePath).filename().string();
    std::ostringstream title;
    title << "plantbench: " << scene << " on " << result.device << ", " << o.size.width << "x" << o.size.height << ", "
          << antialiasingText(o.antialiasing) << ", median of " << o.frames << " frames";
    // With --path every count's point is its worst time's.
    const std::string panelTitle = o.pathTimes ? "Milliseconds per frame, the worst of " +
                                                     std::to_string(*o.pathTimes) + " times along the camera path"
                                               : std::string("Milliseconds per frame");
    std::ostringstream s;
    s << "set terminal " << terminal << " noenhanced size 1100,1200 font 'DejaVu Sans,11'\n"
      << "set output " << quoted(output) << "\n"
      << "set datafile missing 'NaN'\n"
      << "set multiplot layout 2,1 title " << quoted(title.str()) << " font ',13'\n"
      << "set logscale xy\n"
      << "set format x '%.0s%c'\n"
      << xAxis(result) << "set grid xtics ytics mxtics mytics lc rgb '#dddddd'\n"
      << "set key outside right top vertical box opaque\n"
      << "set xlabel 'plants (instances)'\n"
      << "set ylabel 'GPU time per pass, frame wall time (ms)'\n"
      << "set title " << quoted(panelTitle) << "\n"
      << plotCommand(data, false, hasNaive(result)) << "set ylabel 'cost per 1000 plants (ms)'\n"
      << "set title 'Cost per thousand plants: ms x 1000 / plants'\n"
      << plotCommand(data, true, hasNaive(result)) << "unset multiplot\n";
    return s.str();
}

// Runs `gnuplot script` with its stderr in `errors`; its exit status.
int runGnuplot(const fs::path& scriptPath, const fs::path& errors) {
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 2, errors.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
    std::string program = "gnuplot", argument = scriptPath.string();
    char* argv[] = {program.data(), argument.data(), nullptr};
    pid_t pid = 0;
    const int spawned = posix_spawnp(&pid, "gnuplot", &actions, nullptr, argv, environ);
    posix_spawn_file_actions_destroy(&actions);
    if (spawned != 0) throw std::runtime_error(std::string("cannot run gnuplot: ") + std::strerror(spawned));
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {}
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128;
}

std::string readAll(const fs::path& path) {
    std::ifstream in(path);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

// pngcairo draws smoother lines and text; plain png where it is missing.
std::string pngTerminal(const fs::path& dir) {
    const fs::path probe = dir / "terminals.gp";
    std::ofstream(probe) << "set terminal pngcairo\n";
    return runGnuplot(probe, dir / "probe.err") == 0 ? "pngcairo" : "png";
}

} // namespace

void drawPlot(const PlantbenchOptions& o, const SweepResult& result) {
    std::string dirTemplate = (fs::temp_directory_path() / "plantbench-plot-XXXXXX").string();
    if (!mkdtemp(dirTemplate.data()))
        throw std::runtime_error(std::string("cannot create a temporary folder: ") + std::strerror(errno));
    const fs::path dir = dirTemplate;
    const fs::path data = dir / "sweep.dat", scriptPath = dir / "sweep.gp", errors = dir / "gnuplot.err";
    lsys::OutputFile plot(o.plotPath);
    std::ofstream(data) << dataFile(result);
    std::ofstream(scriptPath) << script(o, result, data.string(), pngTerminal(dir), plot.temporaryPath().string());
    const int status = runGnuplot(scriptPath, errors);
    const std::string message = readAll(errors);
    std::error_code ec;
    fs::remove_all(dir, ec);
    if (status != 0 || fs::file_size(plot.temporaryPath(), ec) == 0)
        throw std::runtime_error("gnuplot could not draw '" + o.plotPath + "': " + message);
    plot.commit();
}

} // namespace pf
