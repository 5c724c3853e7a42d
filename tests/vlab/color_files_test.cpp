// cpfg's colour files, read byte for byte as cpfg's irisGL.c reads them: a
// colour map of 256 RGB triples, a material file of 15-byte records; files
// cpfg would read past their end are refused.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "lsystem/vlab/color_files.h"

namespace lsys::vlab {
namespace {

// Each test writes its files into a folder of its own, removed afterwards.
class ColorFiles : public testing::Test {
protected:
    void SetUp() override { std::filesystem::create_directories(folder_); }
    void TearDown() override { std::filesystem::remove_all(folder_); }
    std::filesystem::path file(const std::string& name, const std::string& bytes) const {
        std::ofstream(folder_ / name, std::ios::binary) << bytes;
        return folder_ / name;
    }
    const std::filesystem::path folder_ =
        std::filesystem::temp_directory_path() /
        ("plantfield_colour_" + std::string(testing::UnitTest::GetInstance()->current_test_info()->name()));
};

void expectColor(const glm::vec3& actual, int red, int green, int blue) {
    EXPECT_FLOAT_EQ(actual.r, red / 255.0f);
    EXPECT_FLOAT_EQ(actual.g, green / 255.0f);
    EXPECT_FLOAT_EQ(actual.b, blue / 255.0f);
}

// Entry i of this map is (i, 255 - i, i / 2).
std::string rampMap() {
    std::string bytes;
    for (int i = 0; i < 256; ++i) bytes += {char(i), char(255 - i), char(i / 2)};
    return bytes;
}

// vlab's Lilac (oofs/ext/10-manuals/ext/11-CPFG/ext/Lilac/materials.mat):
// five materials, indices 0, 1, 2, 3 and 4.
const std::string kLilacMaterials("\x00\x00\x00\x00\x00\x00\x00\x00\xa0\xb9\xff\x00\x00\x00\x00"
                                  "\x01\x99\x3a\x27\x3f\xe4\xc5\xff\x07\x07\x07\x43\x2f\x39\x10"
                                  "\x02\x00\x00\x09\x01\x88\xb2\x46\x00\x00\x00\x5f\x5f\x5f\x0c"
                                  "\x03\x00\x28\x18\x0d\xc0\x7a\x4a\x00\x00\x00\x20\x20\x20\x0b"
                                  "\x04\x00\x17\x17\x17\xff\xff\x00\x00\x00\x00\x00\x00\x00\x10",
                                  75);

TEST_F(ColorFiles, ColorMapBytesAreTheColorsOfTheirIndex) {
    const ColorReadResult result = readColorMap(file("plant.map", rampMap()));
    ASSERT_FALSE(result.error.has_value()) << result.error->message;
    for (int i : {0, 1, 128, 254, 255}) {
        const ColorEntry& entry = result.colors[size_t(i)];
        expectColor(entry.diffuse, i, 255 - i, i / 2);
        expectColor(entry.ambient, i, 255 - i, i / 2);
        expectColor(entry.emissive, 0, 0, 0);
        EXPECT_EQ(entry.opacity, 1.0f);
    }
    for (const ColorEntry& entry : result.colors) EXPECT_TRUE(entry.defined);
}

TEST_F(ColorFiles, ColorMapReadsItsFirst256Colors) {
    const ColorReadResult result = readColorMap(file("long.map", rampMap() + "\x01\x02\x03"));
    ASSERT_FALSE(result.error.has_value());
    expectColor(result.colors[0].diffuse, 0, 255, 0);
    expectColor(result.colors[255].diffuse, 255, 0, 127);
}

TEST_F(ColorFiles, ShortColorMapIsRefused) {
    const std::filesystem::path path = file("short.map", rampMap().substr(0, 767));
    const ColorReadResult result = readColorMap(path);
    ASSERT_TRUE(result.error.has_value());
    EXPECT_EQ(result.error->file, path.string());
    EXPECT_NE(result.error->message.find(path.string()), std::string::npos) << result.error->message;
    EXPECT_NE(result.error->message.find("767"), std::string::npos) << result.error->message;
    EXPECT_NE(result.error->expected.find("768"), std::string::npos) << result.error->expected;
    EXPECT_TRUE(readColorMap(file("empty.map", "")).error.has_value());
}

TEST_F(ColorFiles, MaterialRecordsSetTheirIndex) {
    const ColorReadResult result = readMaterialFile(file("materials.mat", kLilacMaterials));
    ASSERT_FALSE(result.error.has_value()) << result.error->message;
    const ColorEntry& bark = result.colors[1]; // 01 99 3a273f e4c5ff 070707 432f39 10
    EXPECT_TRUE(bark.defined);
    EXPECT_FLOAT_EQ(bark.opacity, 1.0f - 0x99 / 255.0f);
    expectColor(bark.ambient, 0x3a, 0x27, 0x3f);
    expectColor(bark.diffuse, 0xe4, 0xc5, 0xff);
    expectColor(bark.emissive, 0x07, 0x07, 0x07);
    expectColor(bark.specular, 0x43, 0x2f, 0x39);
    EXPECT_EQ(bark.shininess, 16.0f); // the byte itself, as cpfg gives it to glMaterialf
    EXPECT_EQ(result.colors[0].opacity, 1.0f);
    expectColor(result.colors[4].diffuse, 0xff, 0xff, 0x00);
    for (size_t i = 0; i < result.colors.size(); ++i) EXPECT_EQ(result.colors[i].defined, i < 5) << i;
    // An index without a record keeps cpfg's default material: white diffuse.
    expectColor(result.colors[200].diffuse, 255, 255, 255);
    expectColor(result.colors[200].ambient, 0, 0, 0);
}

TEST_F(ColorFiles, LaterMaterialRecordReplacesAnEarlierOne) {
    std::string records = kLilacMaterials.substr(15, 15) + kLilacMaterials.substr(15, 15);
    records[15] = char(200); // the second record is index 200
    records[15 + 14] = 100;  // with its own shininess
    records += records.substr(0, 15);
    records[30 + 1] = 0; // and index 1 again, opaque
    const ColorReadResult result = readMaterialFile(file("twice.mat", records));
    ASSERT_FALSE(result.error.has_value());
    EXPECT_EQ(result.colors[1].opacity, 1.0f);
    EXPECT_TRUE(result.colors[200].defined);
    EXPECT_EQ(result.colors[200].shininess, 100.0f);
}

TEST_F(ColorFiles, TruncatedMaterialFileIsRefused) {
    const std::filesystem::path path = file("cut.mat", kLilacMaterials.substr(0, 74));
    const ColorReadResult result = readMaterialFile(path);
    ASSERT_TRUE(result.error.has_value());
    EXPECT_NE(result.error->message.find(path.string()), std::string::npos) << result.error->message;
    EXPECT_NE(result.error->message.find("15"), std::string::npos) << result.error->message;
    const ColorReadResult empty = readMaterialFile(file("empty.mat", ""));
    ASSERT_FALSE(empty.error.has_value()); // no records: every index keeps the default
    EXPECT_FALSE(empty.colors[0].defined);
}

TEST_F(ColorFiles, MissingFilesAreNamed) {
    for (const std::filesystem::path& path : {folder_ / "none.map", folder_}) {
        const ColorReadResult map = readColorMap(path), materials = readMaterialFile(path);
        ASSERT_TRUE(map.error.has_value() && materials.error.has_value());
        EXPECT_NE(map.error->message.find(path.string()), std::string::npos) << map.error->message;
        EXPECT_NE(materials.error->message.find(path.string()), std::string::npos) << materials.error->message;
    }
}

} // namespace
} // namespace lsys::vlab
