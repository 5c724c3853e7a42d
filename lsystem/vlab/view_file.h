#pragma once
// cpfg's view file (.v): how the turtle draws a vlab object and how the
// camera looks at it (Měch 2005, "CPFG Version 4.0 User's Manual", "View
// file"). A list of `label: values` lines, run through the C preprocessor
// first, as cpfg runs it. The turtle's settings (angle, colour and width
// increments, tropism, line style), the surfaces, functions and contours it
// names, and the camera are kept; labels that only concern cpfg's own window
// (fonts, cue range, z buffer…) are read and named in a warning when they
// would change what is drawn.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec3.hpp>

#include "lsystem/common/error.h"
#include "lsystem/language/grammar.h"

namespace lsys::vlab {

// How cpfg draws F: lines `pixels` wide on screen, flat polygons, or cylinders
// ("initial line width: 2 pixels", "line style: cylinder").
enum class LineStyle : uint8_t { Pixel, Polygon, Cylinder };

// "surface: l leaf.s 1 8 4": ~l draws leaf.s scaled by 1, tessellated 8 x 4.
struct ViewSurface {
    std::string id; // the name after ~ (cpfg: one character)
    std::string file;
    float scale = 1.0f;
    int sPrecision = 0; // 0: the file's own
    int tPrecision = 0;
    int texture = -1; // cpfg's texture index (the n-th "texture:" line, from 0); -1: none
    int line = 0;     // in the view file, for diagnostics
};

// "function: internode.func 100": func(1, x) reads internode.func.
struct ViewFunction {
    std::string file;
    int samples = -1; // -1: the file's own
    int line = 0;
};

// "function set: functions.fset": func(i, x) reads the set's i-th function
// (function_file.h, readFunctionSet), before those of any "function:" line.
struct ViewFunctionSet {
    std::string file;
    int line = 0;
    // Whether cpfg names the set's functions for the L-system: a "function:"
    // line after the set turns that off (interpret.c, SetFunctionsFromGallery).
    bool names = true;
};

// "contour: 1 leaf.con".
struct ViewContour {
    int id = 0;
    std::string file;
    int line = 0;
};

// "box: x: -1,1 y: 0,2 z: -1,1": the camera frames this box instead of the
// plant's own bounds (cpfg turns its "auto window" off).
struct ViewBox {
    glm::vec3 min{0.0f};
    glm::vec3 max{1.0f};
};

// cpfg's defaults (interpret.c, InitializeParameters) where a label is absent.
struct ViewFile {
    float angleIncrement = 45.0f; // degrees; "angle factor: n" is 360 / n
    int initialColor = 128;       // colour-map index of the start
    std::optional<int> initialBackColor;
    int colorIncrement = 1;                // of a bare ; and ,
    std::optional<int> backColorIncrement; // "color increment: a b": of the back colour
    float initialLineWidth = 1.0f;
    LineStyle lineStyle = LineStyle::Pixel;
    float lineWidthIncrement = 0.0f; // of a bare ! (down) and # (up)
    bool taperedLines = true;
    int contourSides = 8;
    glm::vec3 tropismDirection{0.0f, 1.0f, 0.0f}; // normalised
    float initialElasticity = 0.0f;
    float elasticityIncrement = 0.0f;
    float initialScale = 1.0f;    // the turtle's scale factor ("initial scale:")
    float scaleMultiplier = 1.0f; // "scale multiplier:"
    // The camera: "viewpoint:", "view reference point:", "twist:",
    // "projection:", "viewing angle:", "scale factor:" (a zoom), "box:".
    glm::vec3 viewpoint{0.0f, 0.0f, 1.0f};
    glm::vec3 viewReferencePoint{0.0f};
    float twist = 0.0f; // degrees
    bool perspective = false;
    float viewingAngle = 45.0f;
    float zoom = 1.0f;
    std::optional<ViewBox> box;
    glm::vec3 lightDirection{1.0f, 0.0f, 0.0f}; // normalised
    std::vector<ViewSurface> surfaces;
    // cpfg's functions: a "function set:" line drops those named before it and
    // its own come first; "function:" lines add theirs after, in file order.
    std::optional<ViewFunctionSet> functionSet;
    std::vector<ViewFunction> functions;
    std::vector<ViewContour> contours;
    std::vector<Movement> movements; // "tropism:" and "torque:", in file order (at most kMaxMovements)
};

struct ViewReadResult {
    ViewFile view;
    std::vector<Diagnostic> diagnostics; // errors at file:line:column
    std::vector<Diagnostic> warnings;    // labels read but not drawn as cpfg draws them
    bool ok() const { return diagnostics.empty(); }
};

// Reads text that has been preprocessed already (`file` names it in diagnostics).
ViewReadResult parseViewFile(std::string_view text, const std::string& file);

// Runs the file through the C preprocessor as cpfg does, then parseViewFile;
// diagnostics point into the user's files.
ViewReadResult readViewFile(const std::filesystem::path& path);

} // namespace lsys::vlab
