// docs/ARCHITECTURE.md against the source tree: every source folder and
// every header of engine/, lsystem/, shaders/ and tools/ is named in the
// section of the map whose heading names its folder, so a file added or
// moved without its line in the map fails here rather than going stale.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

const fs::path kSource = PLANTFIELD_SOURCE_DIR;
constexpr const char* kSourceRoots[] = {"engine", "lsystem", "shaders", "tools"};

struct Section {
    std::string heading;
    std::set<std::string> names; // every word in backticks, and the path parts of each
};

// Splits the map at its headings; each section keeps the names written in
// backticks in it ("`camera.h`", "`scene.h`, `scene_json`", "`components/`"),
// split at commas and spaces, with and without a trailing ".h" or "/".
std::vector<Section> readSections(const fs::path& map) {
    std::ifstream in(map);
    std::vector<Section> sections(1);
    std::string line;
    while (std::getline(in, line)) {
        if (line.rfind('#', 0) == 0) {
            sections.push_back({line, {}});
            continue;
        }
        for (size_t open = line.find('`'); open != std::string::npos;) {
            const size_t close = line.find('`', open + 1);
            if (close == std::string::npos) break;
            std::string code = line.substr(open + 1, close - open - 1);
            std::replace(code.begin(), code.end(), ',', ' ');
            std::istringstream words(code);
            for (std::string word; words >> word;) {
                while (!word.empty() && word.back() == '/') word.pop_back();
                sections.back().names.insert(word);
                if (word.size() > 2 && word.ends_with(".h"))
                    sections.back().names.insert(word.substr(0, word.size() - 2));
            }
            open = line.find('`', close + 1);
        }
    }
    return sections;
}

// Whether the heading names `folder` ("engine/field") as a whole path: not
// "engine/field" inside "engine/field_model", nor "lsystem/" for "lsystem/vlab".
bool headingNames(const std::string& heading, const std::string& folder) {
    for (size_t at = heading.find(folder); at != std::string::npos; at = heading.find(folder, at + 1)) {
        const size_t end = at + folder.size();
        const bool startsWord = at == 0 || heading[at - 1] == ' ' || heading[at - 1] == '`';
        const bool endsWord =
            end == heading.size() || heading[end] == ' ' || heading[end] == '`' ||
            (heading[end] == '/' && (end + 1 == heading.size() || heading[end + 1] == ' ' || heading[end + 1] == '`'));
        if (startsWord && endsWord) return true;
    }
    return false;
}

bool isSource(const fs::path& file) {
    const std::string ext = file.extension().string();
    return ext == ".h" || ext == ".cpp" || ext == ".glsl" || ext == ".vert" || ext == ".frag" || ext == ".comp";
}

// Source folders (holding a source file) under the roots, relative to the
// source tree, and the headers in each.
std::vector<std::pair<std::string, std::vector<std::string>>> sourceFolders() {
    std::vector<std::pair<std::string, std::vector<std::string>>> folders;
    for (const char* root : kSourceRoots) {
        std::vector<fs::path> dirs = {kSource / root};
        for (const auto& entry : fs::recursive_directory_iterator(kSource / root))
            if (entry.is_directory()) dirs.push_back(entry.path());
        std::sort(dirs.begin(), dirs.end());
        for (const fs::path& dir : dirs) {
            std::vector<std::string> headers;
            bool hasSource = false;
            for (const auto& entry : fs::directory_iterator(dir)) {
                if (!entry.is_regular_file() || !isSource(entry.path())) continue;
                hasSource = true;
                if (entry.path().extension() == ".h") headers.push_back(entry.path().stem().string());
            }
            std::sort(headers.begin(), headers.end());
            if (hasSource) folders.emplace_back(fs::relative(dir, kSource).generic_string(), headers);
        }
    }
    return folders;
}

TEST(ArchitectureMap, NamesEverySourceFolderAndHeaderInItsFoldersSection) {
    const std::vector<Section> sections = readSections(kSource / "docs" / "ARCHITECTURE.md");
    std::string missing;
    size_t checked = 0;
    for (const auto& [folder, headers] : sourceFolders()) {
        std::vector<const Section*> own;
        for (const Section& section : sections)
            if (headingNames(section.heading, folder)) own.push_back(&section);
        if (own.empty()) {
            missing += "  no heading names the folder " + folder + "/\n";
            continue;
        }
        for (const std::string& header : headers) {
            ++checked;
            const bool named = std::any_of(own.begin(), own.end(), [&](const Section* s) {
                return s->names.count(header) || s->names.count(header + ".h");
            });
            if (!named) missing += "  " + folder + "/" + header + ".h is not named in the section of " + folder + "/\n";
        }
    }
    EXPECT_GT(checked, 100u) << "the source tree was not found at " << kSource;
    EXPECT_TRUE(missing.empty()) << "docs/ARCHITECTURE.md is out of date with the source tree: give each folder a "
                                    "heading naming it and each header a row (`name` or `name.h`) under it:\n"
                                 << missing;
}

// The check itself: a heading names a folder only as a whole path.
TEST(ArchitectureMap, HeadingsNameFoldersAsWholePaths) {
    EXPECT_TRUE(headingNames("### engine/field", "engine/field"));
    EXPECT_TRUE(headingNames("### `engine/field` (Vulkan)", "engine/field"));
    EXPECT_TRUE(headingNames("## lsystem/ — the language", "lsystem"));
    EXPECT_FALSE(headingNames("### engine/field_model", "engine/field"));
    EXPECT_FALSE(headingNames("### lsystem/vlab", "lsystem"));
    EXPECT_FALSE(headingNames("### the engine/fieldwork", "engine/field"));
}

} // namespace
