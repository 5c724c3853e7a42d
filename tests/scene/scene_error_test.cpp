// Malformed scene files: each must fail with a SceneError that names the file,
// the line and column of the fault and what was expected. None may crash.
#include "scene_test_support.h"

#include <gtest/gtest.h>

namespace pf {
namespace {

#define PF_SPECIES(extra) "{ \"name\": \"a\", " PF_BUSH_LSYSTEM extra " }"
#define PF_OAK_MODEL "\"model\": \"" PLANTFIELD_DATA_DIR "/ramified/oak.ram.json\""
#define PF_MODEL_SPECIES(keys) "{\n  \"species\": [\n    { \"name\": \"m\", " keys " }\n  ]\n}"
#define PF_RIDGE "\"path\": \"" PLANTFIELD_DATA_DIR "/terrain/ridge.lsys\""
#define PF_SCENE(extra) "{\n  \"species\": [" PF_SPECIES("") "]" extra "\n}"
#define PF_CLOUD_FILE "\"" PLANTFIELD_DATA_DIR "/clouds/explosion.lsys\""
#define PF_CLOUDS(cloud) PF_SCENE(",\n  \"clouds\": [\n    " cloud "\n  ]")

struct BadScene {
    const char* name;
    const char* text;
    const char* at;      // the text the error must point at (its first occurrence)
    const char* message; // what the error must say
};

void PrintTo(const BadScene& bad, std::ostream* out) { *out << bad.name; }

class BadSceneTest : public testing::TestWithParam<BadScene> {};

TEST_P(BadSceneTest, FailsWithFileLineColumnAndMessage) {
    const BadScene& bad = GetParam();
    const std::filesystem::path file = test::writeFile("bad.json", bad.text);
    try {
        loadScene(file);
        FAIL() << "loaded without an error";
    } catch (const SceneError& e) {
        const std::string what = e.what();
        EXPECT_EQ(what.rfind(file.string() + ":" + test::lineColumnOf(bad.text, bad.at) + ": ", 0), 0u) << what;
        EXPECT_NE(what.find(bad.message), std::string::npos) << what;
    }
}

INSTANTIATE_TEST_SUITE_P(
    Scene, BadSceneTest,
    testing::Values(
        BadScene{"syntax_error", "{\n  \"seed\": 1,\n  \"species\": [ }\n}", "}", "unexpected '}'"},
        BadScene{"empty_file", "", "", "unexpected end of input"},
        BadScene{"root_not_object", "[1, 2]", "[", "the scene must be an object (got [1, 2])"},
        BadScene{"wrong_type", PF_SCENE(",\n  \"seed\": \"one\""), "\"one\"",
                 "/seed must be an integer ≥ 0 (got \"one\")"},
        BadScene{"fractional_integer", PF_SCENE(",\n  \"seed\": 1.5"), "1.5", "/seed must be an integer ≥ 0"},
        BadScene{"negative_density",
                 "{\n  \"species\": [\n    " PF_SPECIES(", \"placement\": { \"density\": -3 }") "\n  ]\n}", "-3",
                 "/species/0/placement/density must be a number in [0, 100000000] (got -3)"},
        BadScene{"unknown_key_suggestion",
                 "{\n  \"species\": [\n    " PF_SPECIES(", \"placement\": { \"densty\": 3 }") "\n  ]\n}", "\"densty\"",
                 "/species/0/placement/densty is an unknown key; did you mean \"density\"?"},
        BadScene{"unknown_key_list", PF_SCENE(",\n  \"sky\": { \"colour\": [1, 1, 1] }"), "\"colour\"",
                 "/sky/colour is an unknown key (expected one of \"zenith\", \"horizon\")"},
        BadScene{"missing_lsystem_file",
                 "{\n  \"species\": [\n    { \"name\": \"a\", \"lsystem\": \"no_such_plant.lsys\" }\n  ]\n}",
                 "\"no_such_plant.lsys\"", "/species/0/lsystem names a file or folder that does not exist"},
        BadScene{"empty_species", "{\n  \"seed\": 2,\n  \"species\": []\n}", "[]",
                 "/species must list at least one species"},
        BadScene{"missing_species", "{\n  \"seed\": 2\n}", "{", "the scene needs \"species\""},
        BadScene{"zero_resolution", PF_SCENE(",\n  \"terrain\": { \"resolution\": 0 }"), "0 }",
                 "/terrain/resolution must be an integer in [2, 8193] (got 0)"},
        BadScene{"negative_size", PF_SCENE(",\n  \"terrain\": { \"size\": -1 }"), "-1",
                 "/terrain/size must be a number in (0, 1000000] (got -1)"},
        BadScene{"colour_component_out_of_range", PF_SCENE(",\n  \"terrain\": { \"albedo\": [0.5, 2, 0] }"), "[0.5",
                 "/terrain/albedo must be an array of 3 numbers in [0, 1] (got [0.5, 2, 0])"},
        BadScene{"noise_and_image", PF_SCENE(",\n  \"terrain\": { \"noise\": {}, \"image\": { \"path\": \"h.png\" } }"),
                 "\"image\"", "/terrain/image cannot be given together with \"noise\""},
        // L-system mountains (tests/scene/terrain_lsystem_test.cpp loads good ones and a malformed file).
        BadScene{"missing_terrain_lsystem", PF_SCENE(",\n  \"terrain\": { \"lsystem\": \"no_such_ridge.lsys\" }"),
                 "\"no_such_ridge.lsys\"", "/terrain/lsystem names a file or folder that does not exist"},
        BadScene{"terrain_lsystem_without_path", PF_SCENE(",\n  \"terrain\": { \"lsystem\": { \"scale\": 2 } }"),
                 "{ \"scale\"", "/terrain/lsystem needs \"path\""},
        BadScene{"terrain_lsystem_unknown_key",
                 PF_SCENE(",\n  \"terrain\": { \"lsystem\": { " PF_RIDGE ", \"scal\": 2 } }"), "\"scal\"",
                 "/terrain/lsystem/scal is an unknown key; did you mean \"scale\"?"},
        BadScene{"terrain_lsystem_zero_scale",
                 PF_SCENE(",\n  \"terrain\": { \"lsystem\": { " PF_RIDGE ", \"scale\": 0 } }"), "0 }",
                 "/terrain/lsystem/scale must be a number in (0, 1000000] (got 0)"},
        BadScene{"terrain_lsystem_extreme_peak",
                 PF_SCENE(",\n  \"terrain\": { \"lsystem\": { " PF_RIDGE ", \"max_height\": 5 } }"), "{ \"path\"",
                 "/terrain/lsystem (" PLANTFIELD_DATA_DIR "/terrain/ridge.lsys) cannot be made into mountains: "},
        BadScene{"terrain_lsystem_extreme_peak_says_why",
                 PF_SCENE(",\n  \"terrain\": { \"lsystem\": { " PF_RIDGE ", \"max_height\": 5 } }"), "{ \"path\"",
                 "past max_height 5.0 m: keep the turtle's branches within a few steps of its horizontal core"},
        BadScene{"unknown_billboard",
                 "{\n  \"species\": [\n    " PF_SPECIES(", \"lod\": { \"billboard\": \"tripple\" }") "\n  ]\n}",
                 "\"tripple\"",
                 "must be \"single\", \"double\" or \"triple\" (got \"tripple\"); did you mean \"triple\"?"},
        BadScene{"impostor_above_reduced",
                 "{\n  \"species\": [\n    " PF_SPECIES(
                     ", \"lod\": { \"reduced_below_px\": 50, \"impostor_below_px\": 90 }") "\n  ]\n}",
                 "{ \"reduced", "/species/0/lod needs impostor_below_px ≤ reduced_below_px"},
        BadScene{"turbulence_out_of_range", PF_SCENE(",\n  \"wind\": { \"turbulence\": 1.5 }"), "1.5",
                 "/wind/turbulence must be a number in [0, 1] (got 1.5)"},
        BadScene{"joint_budget_too_large", PF_SCENE(",\n  \"physics\": { \"joint_budget\": 20000000 }"), "20000000",
                 "/physics/joint_budget must be an integer in [0, 10000000] (got 20000000)"},
        BadScene{"slope_out_of_range", PF_SCENE(",\n  \"placement\": { \"max_slope\": 120 }"), "120",
                 "/placement/max_slope must be a number in [0, 90] (got 120)"},
        BadScene{"inverted_height_range", PF_SCENE(",\n  \"placement\": { \"height_range\": [5, 1] }"), "[5, 1]",
                 "/placement/height_range must be [low, high] with low ≤ high"},
        BadScene{"density_and_count", PF_SCENE(",\n  \"placement\": { \"density\": 5, \"count\": 9 }"), "\"count\"",
                 "/placement/count cannot be given together with \"density\": density, min_distance, count and "
                 "instances are alternatives"},
        BadScene{"unknown_material",
                 "{\n  \"species\": [\n    " PF_SPECIES(", \"materials\": { \"leef\": [0, 1, 0] }") "\n  ]\n}",
                 "\"leef\"",
                 "/species/0/materials/leef is not a material: use a palette name (bark, leaf, …) or an index 0-255; "
                 "did you mean \"leaf\"?"},
        BadScene{"repeated_species_name",
                 "{\n  \"species\": [\n    " PF_SPECIES("") ",\n    " PF_SPECIES("") "\n  ]\n}",
                 "\"a\", \"lsystem\": \"" PLANTFIELD_DATA_DIR "/plants/stochastic_bush.lsys\" }\n  ]",
                 "/species/1/name repeats the name of /species/0"},
        BadScene{"keyframes_out_of_order",
                 PF_SCENE(",\n  \"camera\": { \"keyframes\": [\n"
                          "    { \"time\": 2, \"position\": [0, 1, 0], \"target\": [1, 1, 0] },\n"
                          "    { \"time\": 1, \"position\": [0, 1, 5], \"target\": [1, 1, 0] } ] }"),
                 "1, \"position\": [0, 1, 5]",
                 "/camera/keyframes/1/time must be at least 0.001 s later than the previous keyframe's time"},
        // Key times near float's largest: the spline's spans and tangents would overflow.
        BadScene{"keyframe_time_absurd",
                 PF_SCENE(",\n  \"camera\": { \"keyframes\": [\n"
                          "    { \"time\": 0, \"position\": [0, 1, 0], \"target\": [1, 1, 0] },\n"
                          "    { \"time\": 3e38, \"position\": [0, 1, 5], \"target\": [1, 1, 0] } ] }"),
                 "3e38", "/camera/keyframes/1/time must be a number in [-100000, 100000] (got 3e38)"},
        BadScene{"keyframes_too_close",
                 PF_SCENE(",\n  \"camera\": { \"keyframes\": [\n"
                          "    { \"time\": 1, \"position\": [0, 1, 0], \"target\": [1, 1, 0] },\n"
                          "    { \"time\": 1.00000001, \"position\": [0, 1, 5], \"target\": [1, 1, 0] } ] }"),
                 "1.00000001", "/camera/keyframes/1/time must be at least 0.001 s later"},
        BadScene{"keyframe_position_absurd",
                 PF_SCENE(",\n  \"camera\": { \"keyframes\": [\n"
                          "    { \"time\": 0, \"position\": [0, 3e30, 0], \"target\": [1, 1, 0] } ] }"),
                 "[0, 3e30, 0]", "/camera/keyframes/0/position must be an array of 3 numbers in [-10000000, 10000000]"},
        BadScene{"fov_out_of_range", PF_SCENE(",\n  \"camera\": { \"fov\": 180 }"), "180",
                 "/camera/fov must be a number in (0, 180) (got 180)"},
        BadScene{"repeated_key", "{\n  \"seed\": 1,\n  \"seed\": 2\n}", "\"seed\": 2",
                 "\"seed\" is given twice in one object"},
        BadScene{"repeated_nested_key", PF_SCENE(",\n  \"fog\": { \"density\": 0.1, \"density\": -3 }"),
                 "\"density\": -3", "\"density\" is given twice in one object"},
        BadScene{"number_overflow", PF_SCENE(",\n  \"fog\": { \"density\": 1e999 }"), "1e999",
                 "a number too large: 1e999"},
        BadScene{"number_beyond_float", PF_SCENE(",\n  \"fog\": { \"density\": 1e300 }"), "1e300",
                 "/fog/density must be a number in [0, 1000000] (got 1e300)"},
        // Species of a model file (tests/scene/model_species_test.cpp loads good ones).
        BadScene{"lsystem_and_model", PF_MODEL_SPECIES(PF_BUSH_LSYSTEM ", " PF_OAK_MODEL), "\"model\"",
                 "/species/0/model and \"lsystem\" both give the plant; keep one"},
        BadScene{"neither", PF_MODEL_SPECIES("\"height\": 3"), "{ \"name\"",
                 "needs \"lsystem\": the L-system file or vlab object folder, or a \"model\""},
        BadScene{"unknown_extension", PF_MODEL_SPECIES("\"model\": \"" PLANTFIELD_DATA_DIR "/plants/broadleaf.lsys\""),
                 "\"" PLANTFIELD_DATA_DIR "/plants/broadleaf.lsys\"",
                 "/species/0/model must name a ramification tree (.ram.json) or a component plant "
                 "(.comp.json), not \"broadleaf.lsys\""},
        BadScene{"missing_model", PF_MODEL_SPECIES("\"model\": \"no_such_tree.ram.json\""), "\"no_such_tree.ram.json\"",
                 "/species/0/model names a file that does not exist"},
        BadScene{"defines_with_model", PF_MODEL_SPECIES(PF_OAK_MODEL ", \"defines\": { \"r\": 1 }"), "\"defines\"",
                 "/species/0/defines is an L-system setting; a species with a \"model\" has none"},
        BadScene{"steps_with_model", PF_MODEL_SPECIES(PF_OAK_MODEL ", \"steps\": 4"), "\"steps\"",
                 "/species/0/steps is an L-system setting; a species with a \"model\" has none"},
        // Clouds (tests/scene/cloud_scene_test.cpp loads good ones).
        BadScene{"clouds_not_array", PF_SCENE(",\n  \"clouds\": { \"lsystem\": 1 }"), "{ \"lsystem\"",
                 "/clouds must be an array of clouds"},
        BadScene{"cloud_unknown_key",
                 PF_CLOUDS("{ \"lsystem\": " PF_CLOUD_FILE ", \"position\": [0, 99, 0], \"colour\": 1 }"), "\"colour\"",
                 "/clouds/0/colour is an unknown key (expected one of \"lsystem\", \"position\""},
        BadScene{"cloud_without_lsystem", PF_CLOUDS("{ \"position\": [0, 99, 0] }"), "{ \"position\"",
                 "needs \"lsystem\": the cloud's L-system file"},
        BadScene{"cloud_without_position", PF_CLOUDS("{ \"lsystem\": " PF_CLOUD_FILE " }"), "{ \"lsystem\"",
                 "needs \"position\": [x, y, z] in metres"},
        BadScene{"missing_cloud_file", PF_CLOUDS("{ \"lsystem\": \"no_such_cloud.lsys\", \"position\": [0, 99, 0] }"),
                 "\"no_such_cloud.lsys\"", "/clouds/0/lsystem names a file that does not exist"},
        BadScene{"cloud_position_of_two", PF_CLOUDS("{ \"lsystem\": " PF_CLOUD_FILE ", \"position\": [0, 99] }"),
                 "[0, 99]", "/clouds/0/position must be"},
        BadScene{"cloud_size_zero",
                 PF_CLOUDS("{ \"lsystem\": " PF_CLOUD_FILE ", \"position\": [0, 99, 0], \"size\": 0 }"), "0 }",
                 "/clouds/0/size must be a number in (0, 1000000] (got 0)"},
        BadScene{"cloud_shadow_not_boolean",
                 PF_CLOUDS("{ \"lsystem\": " PF_CLOUD_FILE ", \"position\": [0, 99, 0], \"shadow\": 1 }"), "1 }",
                 "/clouds/0/shadow must be true or false"},
        BadScene{"cloud_without_spheres",
                 PF_CLOUDS("{ \"lsystem\": \"" PLANTFIELD_DATA_DIR
                           "/plants/fractal_tree.lsys\", \"position\": [0, 99, 0] }"),
                 "\"" PLANTFIELD_DATA_DIR "/plants/fractal_tree.lsys\"",
                 "/clouds/0/lsystem makes no cloud: draws no sphere"},
        // Every number has a bound that keeps what is computed from it finite.
        BadScene{"sun_intensity_near_float_max", PF_SCENE(",\n  \"sun\": { \"intensity\": 3e38 }"), "3e38",
                 "/sun/intensity must be a number in [0, 1000000] (got 3e38)"},
        BadScene{"plant_position_past_the_world",
                 "{\n  \"species\": [" PF_SPECIES(
                     ", \"placement\": { \"instances\": [{ \"position\": [1e30, 0] }] }") "]\n}",
                 "[1e30, 0]",
                 "/species/0/placement/instances/0/position must be an array of 2 numbers in [-10000000, 10000000] "
                 "(got [1e30, 0])"},
        BadScene{"wind_speed_near_float_max", PF_SCENE(",\n  \"wind\": { \"speed\": 1e37 }"), "1e37",
                 "/wind/speed must be a number in [0, 1000000] (got 1e37)"},
        BadScene{"lacunarity_that_overflows_the_octaves",
                 PF_SCENE(",\n  \"terrain\": { \"noise\": { \"octaves\": 16, \"lacunarity\": 1000 } }"), "1000",
                 "/terrain/noise/lacunarity must be a number in [1, 16] (got 1000)"},
        BadScene{"youngs_modulus_past_steel", PF_SCENE(",\n  \"physics\": { \"youngs_modulus\": 1e20 }"), "1e20",
                 "/physics/youngs_modulus must be a number in (0, 10000000000000] (got 1e20)"},
        BadScene{"cloud_far_out", PF_CLOUDS("{ \"lsystem\": " PF_CLOUD_FILE ", \"position\": [0, 3e38, 0] }"),
                 "[0, 3e38, 0]",
                 "/clouds/0/position must be an array of 3 numbers in [-10000000, 10000000] (got [0, 3e38, 0])"},
        BadScene{"camera_far_past_the_world", PF_SCENE(",\n  \"camera\": { \"far\": 1e9 }"), "1e9",
                 "/camera/far must be a number in (0.1, 1000000] (got 1e9)"}),
    [](const testing::TestParamInfo<BadScene>& info) { return std::string(info.param.name); });

TEST(SceneErrors, AMissingFileIsASceneError) {
    EXPECT_THROW(loadScene(test::testFolder() / "absent.json"), SceneError);
    EXPECT_THROW(loadScene(test::testFolder()), SceneError); // a folder, not a file
}

TEST(SceneErrors, DeepNestingAndBinaryInputFailWithoutCrashing) {
    const std::string deep = std::string(100000, '[') + std::string(100000, ']');
    const std::filesystem::path deepFile = test::writeFile("deep.json", deep);
    try {
        loadScene(deepFile);
        FAIL() << "a scene nesting 100000 levels loaded";
    } catch (const SceneError& e) { // refused at the bracket past JsonDocumentKind::maxDepth
        EXPECT_EQ(std::string(e.what()), deepFile.string() + ":1:65: the scene nests deeper than 64 levels");
    }
    const std::string binary("\x00\xff\xfe{\x01\"", 6);
    EXPECT_THROW(loadScene(test::writeFile("binary.json", binary)), SceneError);
}

} // namespace
} // namespace pf
