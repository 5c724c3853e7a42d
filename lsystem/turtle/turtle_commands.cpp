#include "lsystem/turtle/turtle_commands.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include "lsystem/turtle/turtle.h"
#include "lsystem/turtle/turtle_frame.h"

namespace lsys {

namespace {

// The angle of a turn: its parameter, or the current angle.
float turnAngle(const TurtleStep& t) { return t.parameterOr(0, t.state.angle); }

// cpfg's colour map has 256 entries and its index wraps around it (interpret.c,
// ';' and ','): 256 is 0 and -1 is 255. Parameters are arbitrary floats,
// truncated as C converts them; applyModule() has already refused NaN.
uint32_t materialIndex(float value) {
    const double wrapped = std::fmod(std::trunc(static_cast<double>(value)), 256.0);
    return static_cast<uint32_t>(wrapped < 0.0 ? wrapped + 256.0 : wrapped);
}

// A bare ! or # (direction -1 or +1): ABOP's factor, then cpfg's increment;
// never below 0.
float stepWidth(const TurtleStep& t, float direction) {
    const float factor = direction < 0.0f ? t.settings.widthFactor : 1.0f / t.settings.widthFactor;
    return std::max(0.0f, t.state.width * factor + direction * t.settings.widthIncrement);
}

// A bare ; or , (direction +1 or -1) steps the index by the colour increment.
float stepMaterial(const TurtleStep& t, int direction) {
    return static_cast<float>(static_cast<int64_t>(t.state.material) + direction * t.settings.colorIncrement);
}

// A segment drawn backwards (negative length) faces the other way.
Frame segmentFrame(const TurtleState& s, float length) {
    Frame frame = frameOf(s);
    if (length < 0.0f) frame.rotation = frame.rotation * glm::angleAxis(glm::radians(180.0f), glm::vec3(0, 0, 1));
    return frame;
}

// A vertex of the innermost open polygon, if there is one.
void addVertex(TurtleStack& stack, glm::vec3 position) {
    if (!stack.polygons.empty()) stack.polygons.back().outline.push_back(position);
}

// Moves along H; inside a polygon the new position is one of its vertices.
// cpfg's g (and f in a polygon); cpfg turns by its movements before any step (interpret.c, f and g).
void moveWithoutVertex(const TurtleStep& t) {
    adjustForMovements(t.state, t.settings.movements);
    t.state.position += t.state.heading * t.parameterOr(0, t.state.length);
}

void move(const TurtleStep& t) {
    moveWithoutVertex(t);
    addVertex(t.stack, t.state.position);
}

// cpfg turns by its movements before the segment, by the tropism of
// "tropism direction:" after it (interpret.c, F).
void drawSegment(const TurtleStep& t) {
    TurtleState& s = t.state;
    adjustForMovements(s, t.settings.movements);
    const float length = t.parameterOr(0, s.length);
    const float startWidth = s.width;
    s.width = t.parameterOr(1, s.width);
    s.joint = t.out.addSegment(segmentFrame(s, length), std::abs(length), startWidth * 0.5f, s.width * 0.5f, s.material,
                               s.joint, s.stiffness);
    s.position += s.heading * length;
    bendTowardTropism(s, t.settings.cpfgModules);
    s.segmentHeading = s.heading;
    s.segmentUp = s.up;
}

void popBranch(const TurtleStep& t) {
    if (t.stack.branches.empty()) return;
    t.state = t.stack.branches.back();
    t.stack.branches.pop_back();
}

void closePolygon(const TurtleStep& t) {
    if (t.stack.polygons.empty()) return;
    OpenPolygon polygon = std::move(t.stack.polygons.back());
    t.stack.polygons.pop_back();
    std::vector<glm::vec3> outline;
    for (const glm::vec3& p : polygon.outline)
        if (outline.empty() || glm::distance(p, outline.back()) > 1e-6f) outline.push_back(p);
    if (outline.size() > 1 && glm::distance(outline.front(), outline.back()) <= 1e-6f) outline.pop_back();
    if (outline.size() >= 3) t.out.addPolygon(polygon.start, std::move(outline), polygon.material, polygon.joint);
}

void changeNothing(const TurtleStep&) {}

// Widths are diameters and angles degrees; bare modules of the @ families
// change nothing, which their defaults (x = 1, x = 0, x = the field) say.
// An entry left out does not compile: TurtleReads and StyleChange have no default.
constexpr std::array<TurtleCommandDefinition, kTurtleActions> kDefinitions = {{
    {.action = TurtleAction::None,
     .symbol = "@Oc",
     .documentation = "nothing (cpfg's unfilled screen-space circle), as every module not listed here",
     .reads = {kReadsNothing},
     .changes = kChangesNoStyle,
     .stacks = kKeepsStacks,
     .apply = changeNothing},
    // Its joint's parent is the joint the turtle is on (TurtleState::joint);
    // a negative l draws backwards, turned 180 degrees about U.
    {.action = TurtleAction::Draw,
     .symbol = "F",
     .parameters = "l = length, w = width",
     .documentation = "draw a segment (a joint) of length l tapering from the width to w, then bend by tropism; "
                      "in a polygon, f",
     .reads = {kReadsWidth | kReadsMaterial | kReadsStiffness | kReadsElasticity | kReadsPolygonOpen, kReadsLength,
               kReadsTropism},
     .changes = {StyleField::Width, FieldChange::Set, FieldChange::Keep},
     // cpfg and lpfg trace a polygon's outline with F too: Robbins' {+F-F-F} is a triangle.
     .stacks = kKeepsStacks,
     .inPolygon = TurtleAction::Move,
     .apply = drawSegment},
    {.action = TurtleAction::Move,
     .symbol = "f",
     .parameters = "l = length",
     .documentation = "move by l without drawing; in a polygon, record where it ends as a vertex",
     .reads = {kReadsPolygonOpen, kReadsLength},
     .changes = kChangesNoStyle,
     .stacks = kKeepsStacks,
     .apply = move},
    // cpfg's G and g (interpret.c): as F and f, but inside a polygon they
    // record no vertex, so ABOP Fig 5.5's leaf edge G G G spans one side.
    {.action = TurtleAction::DrawWithoutVertex,
     .symbol = "G",
     .cpfgOnly = true,
     .parameters = "l = length, w = width",
     .documentation = "(cpfg files) as F, but in a polygon it moves without recording a vertex",
     .reads = {kReadsWidth | kReadsMaterial | kReadsStiffness | kReadsElasticity | kReadsPolygonOpen, kReadsLength,
               kReadsTropism},
     .changes = {StyleField::Width, FieldChange::Set, FieldChange::Keep},
     .stacks = kKeepsStacks,
     .inPolygon = TurtleAction::MoveWithoutVertex,
     .apply = drawSegment},
    {.action = TurtleAction::MoveWithoutVertex,
     .symbol = "g",
     .cpfgOnly = true,
     .parameters = "l = length",
     .documentation = "(cpfg files) move by l without drawing or recording a vertex",
     // It acts for G inside a polygon, where G draws nothing: what it does
     // then depends on the polygon being open (an InstanceGraph key reads it).
     .reads = {kReadsPolygonOpen, kReadsLength},
     .changes = kChangesNoStyle,
     .stacks = kKeepsStacks,
     .apply = moveWithoutVertex},
    {.action = TurtleAction::Yaw,
     .symbol = "+",
     .parameters = "a = angle",
     .documentation = "yaw by a degrees about U, towards L",
     .reads = {kReadsNothing, kReadsAngle},
     .changes = kChangesNoStyle,
     .stacks = kKeepsStacks,
     .apply = [](const TurtleStep& t) { rotate(t.state, t.state.up, turnAngle(t)); }},
    {.action = TurtleAction::YawBack,
     .symbol = "-",
     .parameters = "a = angle",
     .documentation = "yaw by a degrees about U, away from L",
     .reads = {kReadsNothing, kReadsAngle},
     .changes = kChangesNoStyle,
     .stacks = kKeepsStacks,
     .apply = [](const TurtleStep& t) { rotate(t.state, t.state.up, -turnAngle(t)); }},
    {.action = TurtleAction::Pitch,
     .symbol = "&",
     .parameters = "a = angle",
     .documentation = "pitch down by a degrees about L",
     .reads = {kReadsNothing, kReadsAngle},
     .changes = kChangesNoStyle,
     .stacks = kKeepsStacks,
     .apply = [](const TurtleStep& t) { rotate(t.state, t.state.left, turnAngle(t)); }},
    {.action = TurtleAction::PitchBack,
     .symbol = "^",
     .parameters = "a = angle",
     .documentation = "pitch up by a degrees about L",
     .reads = {kReadsNothing, kReadsAngle},
     .changes = kChangesNoStyle,
     .stacks = kKeepsStacks,
     .apply = [](const TurtleStep& t) { rotate(t.state, t.state.left, -turnAngle(t)); }},
    {.action = TurtleAction::Roll,
     .symbol = "\\",
     .parameters = "a = angle",
     .documentation = "roll left by a degrees about H",
     .reads = {kReadsNothing, kReadsAngle},
     .changes = kChangesNoStyle,
     .stacks = kKeepsStacks,
     .apply = [](const TurtleStep& t) { rotate(t.state, t.state.heading, turnAngle(t)); }},
    {.action = TurtleAction::RollBack,
     .symbol = "/",
     .parameters = "a = angle",
     .documentation = "roll right by a degrees about H",
     .reads = {kReadsNothing, kReadsAngle},
     .changes = kChangesNoStyle,
     .stacks = kKeepsStacks,
     .apply = [](const TurtleStep& t) { rotate(t.state, t.state.heading, -turnAngle(t)); }},
    {.action = TurtleAction::TurnAround,
     .symbol = "|",
     .documentation = "turn 180 degrees about U",
     .reads = {kReadsNothing},
     .changes = kChangesNoStyle,
     .stacks = kKeepsStacks,
     .apply = [](const TurtleStep& t) { rotate(t.state, t.state.up, 180.0f); }},
    {.action = TurtleAction::RollHorizontal,
     .symbol = "$",
     .alias = "@v", // cpfg's name: its $ ends a sub-L-system, and one that ends none is skipped
     .symbolNotInCpfg = true,
     .documentation = "roll about H until L is horizontal (ABOP: L = V x H / |V x H|, V = +Y); in cpfg files @v only",
     .reads = {kReadsWorldUp},
     .changes = kChangesNoStyle,
     .stacks = kKeepsStacks,
     .apply = [](const TurtleStep& t) { rollHorizontal(t.state); }},
    // cpfg's @M and @R (blackbox.c, 'M' and 'R'): the point and the
    // heading are in plant space; neither records a polygon vertex.
    {.action = TurtleAction::MoveTo,
     .symbol = "@M",
     .cpfgOnly = true,
     .parameters = "x, y, z = 0",
     .documentation = "(cpfg files) move to the point (x, y, z) without drawing (with fewer than 2 parameters, "
                      "nothing happens)",
     .reads = {kReadsPlantFrame},
     .changes = kChangesNoStyle,
     .stacks = kKeepsStacks,
     .apply =
         [](const TurtleStep& t) {
             if (t.parameters.size() >= 2) t.state.position = {t.parameters[0], t.parameters[1], t.parameterOr(2, 0)};
         }},
    {.action = TurtleAction::SetHeading,
     .symbol = "@R",
     .cpfgOnly = true,
     .parameters = "hx, hy, hz = 0, ux, uy, uz",
     .documentation = "(cpfg files) set H to (hx, hy, hz) normalised, and U to -(ux, uy, uz) (cpfg's up is L x H) "
                      "if that is perpendicular to H, else to the last segment's U turned as H turned from the "
                      "last segment's (with fewer than 2 parameters, nothing happens)",
     .reads = {kReadsPlantFrame},
     .changes = kChangesNoStyle,
     .stacks = kKeepsStacks,
     .apply = [](const TurtleStep& t) { setHeadingAsCpfg(t.state, t.parameters); }},
    // Only the branch stack: open polygons are not popped (ABOP Fig 5.6's
    // [+A{.].C.} closes after the branch a polygon opened in it).
    {.action = TurtleAction::Push,
     .symbol = "[",
     .documentation = "push the turtle state",
     .reads = {kReadsNothing},
     .changes = kChangesNoStyle,
     .stacks = {1, 0},
     .apply = [](const TurtleStep& t) { t.stack.branches.push_back(t.state); }},
    {.action = TurtleAction::Pop,
     .symbol = "]",
     .documentation = "pop the turtle state (with nothing pushed, nothing happens)",
     .reads = {kReadsNothing},
     .changes = kChangesNoStyle,
     .stacks = {-1, 0},
     .apply = popBranch},
    // A vlab object's view file sets cpfg's increments (TurtleSettings): its
    // bare ! subtracts the line width increment instead.
    {.action = TurtleAction::Width,
     .symbol = "!",
     .parameters = "w = width * 0.7",
     .documentation = "set the width to w (0.7 is TurtleSettings::widthFactor; a vlab object's bare ! subtracts "
                      "its line width increment)",
     .reads = {kReadsNothing},
     .changes = {StyleField::Width, FieldChange::Set, FieldChange::Derive},
     .stacks = kKeepsStacks,
     .apply = [](const TurtleStep& t) { t.state.width = t.parameterOr(0, stepWidth(t, -1.0f)); }},
    {.action = TurtleAction::Widen,
     .symbol = "#",
     .parameters = "w = width / 0.7",
     .documentation = "set the width to w (cpfg's width increase: a bare # undoes a bare !)",
     .reads = {kReadsNothing},
     .changes = {StyleField::Width, FieldChange::Set, FieldChange::Derive},
     .stacks = kKeepsStacks,
     .apply = [](const TurtleStep& t) { t.state.width = t.parameterOr(0, stepWidth(t, 1.0f)); }},
    {.action = TurtleAction::Material,
     .symbol = ";",
     .alias = "'",
     .parameters = "i = material + 1",
     .documentation = "set the material index to i, modulo 256 (cpfg's colour map; a vlab object's bare ; adds "
                      "its colour increment)",
     .reads = {kReadsNothing},
     .changes = {StyleField::Material, FieldChange::Set, FieldChange::Derive},
     .stacks = kKeepsStacks,
     .apply = [](const TurtleStep& t) { t.state.material = materialIndex(t.parameterOr(0, stepMaterial(t, 1))); }},
    {.action = TurtleAction::MaterialDown,
     .symbol = ",",
     .parameters = "i = material - 1",
     .documentation = "set the material index to i, modulo 256 (cpfg's colour decrement)",
     .reads = {kReadsNothing},
     .changes = {StyleField::Material, FieldChange::Set, FieldChange::Derive},
     .stacks = kKeepsStacks,
     .apply = [](const TurtleStep& t) { t.state.material = materialIndex(t.parameterOr(0, stepMaterial(t, -1))); }},
    // A string-level operation, not a state transition: interpretModules()
    // skips to the ] (and the rewriter already removes % produced by rules).
    {.action = TurtleAction::Cut,
     .symbol = "%",
     .documentation = "cut the rest of the branch, up to its ]",
     .reads = {kReadsNothing},
     .changes = kChangesNoStyle,
     .stacks = {0, 0, true},
     .apply = changeNothing},
    {.action = TurtleAction::ScaleLength,
     .symbol = "@Lm",
     .parameters = "x = 1",
     .documentation = "multiply the length of a bare F or f by x",
     .reads = {kReadsNothing},
     .changes = {StyleField::Length, FieldChange::Derive, FieldChange::Keep},
     .stacks = kKeepsStacks,
     .apply = [](const TurtleStep& t) { t.state.length *= t.parameterOr(0, 1.0f); }},
    {.action = TurtleAction::AddLength,
     .symbol = "@La",
     .parameters = "x = 0",
     .documentation = "add x to the length of a bare F or f",
     .reads = {kReadsNothing},
     .changes = {StyleField::Length, FieldChange::Derive, FieldChange::Keep},
     .stacks = kKeepsStacks,
     .apply = [](const TurtleStep& t) { t.state.length += t.parameterOr(0, 0.0f); }},
    {.action = TurtleAction::SetLength,
     .symbol = "@Ls",
     .parameters = "x = length",
     .documentation = "set the length of a bare F or f to x",
     .reads = {kReadsNothing},
     .changes = {StyleField::Length, FieldChange::Set, FieldChange::Keep},
     .stacks = kKeepsStacks,
     .apply = [](const TurtleStep& t) { t.state.length = t.parameterOr(0, t.state.length); }},
    {.action = TurtleAction::ScaleAngle,
     .symbol = "@Am",
     .parameters = "x = 1",
     .documentation = "multiply the angle of a bare turn by x",
     .reads = {kReadsNothing},
     .changes = {StyleField::Angle, FieldChange::Derive, FieldChange::Keep},
     .stacks = kKeepsStacks,
     .apply = [](const TurtleStep& t) { t.state.angle *= t.parameterOr(0, 1.0f); }},
    {.action = TurtleAction::AddAngle,
     .symbol = "@Aa",
     .parameters = "x = 0",
     .documentation = "add x to the angle of a bare turn",
     .reads = {kReadsNothing},
     .changes = {StyleField::Angle, FieldChange::Derive, FieldChange::Keep},
     .stacks = kKeepsStacks,
     .apply = [](const TurtleStep& t) { t.state.angle += t.parameterOr(0, 0.0f); }},
    {.action = TurtleAction::SetAngle,
     .symbol = "@As",
     .parameters = "x = angle",
     .documentation = "set the angle of a bare turn to x",
     .reads = {kReadsNothing},
     .changes = {StyleField::Angle, FieldChange::Set, FieldChange::Keep},
     .stacks = kKeepsStacks,
     .apply = [](const TurtleStep& t) { t.state.angle = t.parameterOr(0, t.state.angle); }},
    {.action = TurtleAction::ScaleWidth,
     .symbol = "@Wm",
     .parameters = "x = 1",
     .documentation = "multiply the width by x",
     .reads = {kReadsNothing},
     .changes = {StyleField::Width, FieldChange::Derive, FieldChange::Keep},
     .stacks = kKeepsStacks,
     .apply = [](const TurtleStep& t) { t.state.width *= t.parameterOr(0, 1.0f); }},
    {.action = TurtleAction::AddWidth,
     .symbol = "@Wa",
     .parameters = "x = 0",
     .documentation = "add x to the width",
     .reads = {kReadsNothing},
     .changes = {StyleField::Width, FieldChange::Derive, FieldChange::Keep},
     .stacks = kKeepsStacks,
     .apply = [](const TurtleStep& t) { t.state.width += t.parameterOr(0, 0.0f); }},
    {.action = TurtleAction::AddMaterial,
     .symbol = "@Ca",
     .parameters = "x = 0",
     .documentation = "add x to the material index, modulo 256 as by ;",
     .reads = {kReadsNothing},
     .changes = {StyleField::Material, FieldChange::Derive, FieldChange::Keep},
     .stacks = kKeepsStacks,
     .apply =
         [](const TurtleStep& t) {
             t.state.material = materialIndex(static_cast<float>(t.state.material) + t.parameterOr(0, 0.0f));
         }},
    // Crankshaw's F(l,k) arrives as @K(k)F(l) through the dialect's interpretation rules.
    {.action = TurtleAction::Stiffness,
     .symbol = "@K",
     .parameters = "k = stiffness",
     .documentation = "set the spring stiffness of the following segments' joints (0: from beam theory)",
     .reads = {kReadsNothing},
     .changes = {StyleField::Stiffness, FieldChange::Set, FieldChange::Keep},
     .stacks = kKeepsStacks,
     .apply = [](const TurtleStep& t) { t.state.stiffness = t.parameterOr(0, t.state.stiffness); }},
    // |T| scales the bend, e < 0 bends away, e = 0 (the default) does not bend.
    // In cpfg files the elasticity it declares it sets stays the view
    // file's for the whole plant (cpfg's @Ts sets a movement's), so no
    // InstanceGraph key can differ by it.
    {.action = TurtleAction::Elasticity,
     .symbol = "@Ts",
     .parameters = "e = elasticity",
     .documentation = "set the elasticity: after each segment H turns toward T by e*|H x T| radians (ABOP section "
                      "2.4); in cpfg files by asin(e T.U) toward U, then by asin(e T.L) toward L (cpfg's bend), "
                      "and there @Ts(k, e = 0) sets the elasticity of the view file's k-th tropism or torque instead",
     .reads = {kReadsNothing},
     .changes = {StyleField::Elasticity, FieldChange::Set, FieldChange::Keep},
     .stacks = kKeepsStacks,
     .apply =
         [](const TurtleStep& t) {
             if (t.settings.cpfgModules)
                 changeMovementElasticity(t.state, t.settings.movements, ElasticityChange::Set, t.parameters);
             else
                 t.state.elasticity = t.parameterOr(0, t.state.elasticity);
         }},
    {.action = TurtleAction::TropismVector,
     .symbol = "@Tv",
     .parameters = "x, y, z",
     .documentation = "set the tropism vector T, in plant space (with fewer parameters, nothing happens)",
     .reads = {kReadsNothing},
     .changes = {StyleField::Tropism, FieldChange::SetInPlant, FieldChange::Keep},
     .stacks = kKeepsStacks,
     .apply =
         [](const TurtleStep& t) {
             if (t.parameters.size() >= 3) t.state.tropism = {t.parameters[0], t.parameters[1], t.parameters[2]};
         }},
    // A movement's elasticity is no StyleField: a plant with movements is
    // one object of the InstanceGraph (lsystem/instancing/instance_graph_build.cpp).
    {.action = TurtleAction::MovementElasticityUp,
     .symbol = "@Ti",
     .cpfgOnly = true,
     .parameters = "k, d = increment",
     .documentation = "(cpfg files) add d to the elasticity of the view file's k-th tropism or torque",
     .reads = {kReadsNothing},
     .changes = kChangesNoStyle,
     .stacks = kKeepsStacks,
     .apply =
         [](const TurtleStep& t) {
             changeMovementElasticity(t.state, t.settings.movements, ElasticityChange::Increase, t.parameters);
         }},
    {.action = TurtleAction::MovementElasticityDown,
     .symbol = "@Td",
     .cpfgOnly = true,
     .parameters = "k, d = increment",
     .documentation = "(cpfg files) subtract d from the elasticity of the view file's k-th tropism or torque",
     .reads = {kReadsNothing},
     .changes = kChangesNoStyle,
     .stacks = kKeepsStacks,
     .apply =
         [](const TurtleStep& t) {
             changeMovementElasticity(t.state, t.settings.movements, ElasticityChange::Decrease, t.parameters);
         }},
    {.action = TurtleAction::Sphere,
     .symbol = "@O",
     .parameters = "d = width",
     .documentation = "draw a sphere of diameter d",
     .reads = {kReadsMaterial, kReadsWidth},
     .changes = kChangesNoStyle,
     .stacks = kKeepsStacks,
     .apply =
         [](const TurtleStep& t) {
             t.out.addSphere(frameOf(t.state), 0.5f * t.parameterOr(0, t.state.width), t.state.material, t.state.joint);
         }},
    // A surface grows from its origin along H, spreads along L and faces U.
    {.action = TurtleAction::Surface,
     .symbol = "~",
     .symbolIsPrefix = true,
     .parameters = "s = 1",
     .documentation = "draw the surface `name` scaled by s: leaf, petal, a mesh of data/meshes or a vlab object's "
                      ".s file (which moves the turtle to its end point)",
     .reads = {kReadsMaterial},
     .changes = kChangesNoStyle,
     .stacks = kKeepsStacks,
     .apply =
         [](const TurtleStep& t) {
             const float scale = t.parameterOr(0, 1.0f);
             // cpfg leaves the turtle at the surface's end point (patches.c).
             const glm::vec3 end =
                 t.out.addSurface(t.command.surface, frameOf(t.state), scale, t.state.material, t.state.joint);
             t.state.position += (-end.x * t.state.left + end.y * t.state.heading + end.z * t.state.up) * scale;
         }},
    {.action = TurtleAction::PolygonBegin,
     .symbol = "{",
     .documentation = "open a polygon with the frame, material and joint here",
     .reads = {kReadsMaterial},
     .changes = kChangesNoStyle,
     .stacks = {0, 1},
     .apply =
         [](const TurtleStep& t) {
             t.stack.polygons.push_back({frameOf(t.state), t.state.material, t.state.joint, {}});
         }},
    {.action = TurtleAction::PolygonVertex,
     .symbol = ".",
     .documentation = "record the position as a vertex of the innermost open polygon",
     .reads = {kReadsPolygonOpen},
     .changes = kChangesNoStyle,
     .stacks = kKeepsStacks,
     .apply = [](const TurtleStep& t) { addVertex(t.stack, t.state.position); }},
    {.action = TurtleAction::PolygonEnd,
     .symbol = "}",
     .documentation = "close the innermost polygon, drawn when it has 3 or more distinct vertices",
     .reads = {kReadsNothing},
     .changes = kChangesNoStyle,
     .stacks = {0, -1},
     .apply = closePolygon},
}};

constexpr std::array<std::string_view, 2> symbolsOf(const TurtleCommandDefinition& definition) {
    return {definition.symbol, definition.alias};
}

// Each command at its action's index, with a symbol, a line of documentation and a transition.
constexpr bool everyCommandIsDefined() {
    for (size_t i = 0; i < kDefinitions.size(); ++i) {
        const TurtleCommandDefinition& definition = kDefinitions[i];
        if (static_cast<size_t>(definition.action) != i || definition.symbol.empty() ||
            definition.documentation.empty() || definition.apply == nullptr)
            return false;
    }
    return true;
}
static_assert(everyCommandIsDefined(), "every TurtleAction needs its definition, in enum order");

// A module name means one command: no symbol repeats, none starts with a prefix symbol.
constexpr bool symbolsAreUnambiguous() {
    for (size_t a = 0; a < kDefinitions.size(); ++a)
        for (size_t i = 0; i < 2; ++i)
            for (size_t b = 0; b < kDefinitions.size(); ++b)
                for (size_t j = 0; j < 2; ++j) {
                    const std::string_view symbol = symbolsOf(kDefinitions[a])[i];
                    const std::string_view other = symbolsOf(kDefinitions[b])[j];
                    if (symbol.empty() || other.empty() || (a == b && i == j)) continue;
                    if (symbol == other || (kDefinitions[b].symbolIsPrefix && symbol.starts_with(other))) return false;
                }
    return true;
}
static_assert(symbolsAreUnambiguous(), "two turtle commands share a module name");

} // namespace

std::span<const TurtleCommandDefinition, kTurtleActions> turtleCommandDefinitions() { return kDefinitions; }

const TurtleCommandDefinition& turtleCommandDefinition(TurtleAction action) {
    return kDefinitions[static_cast<size_t>(action)];
}

const TurtleCommandDefinition& actingDefinition(TurtleAction action, size_t openPolygons) {
    const TurtleCommandDefinition& definition = turtleCommandDefinition(action);
    return openPolygons > 0 && definition.inPolygon ? turtleCommandDefinition(*definition.inPolygon) : definition;
}

size_t parameterCount(const TurtleCommandDefinition& definition) {
    const std::string_view list = definition.parameters;
    return list.empty() ? 0 : static_cast<size_t>(std::count(list.begin(), list.end(), ',')) + 1;
}

bool drawsSegment(TurtleAction action, size_t openPolygons) {
    return openPolygons == 0 && (action == TurtleAction::Draw || action == TurtleAction::DrawWithoutVertex);
}

TurtleCommand turtleCommand(const std::string& name, bool cpfgModules) {
    static const std::unordered_map<std::string_view, TurtleAction> exact = [] {
        std::unordered_map<std::string_view, TurtleAction> actions;
        for (const TurtleCommandDefinition& definition : kDefinitions)
            if (!definition.symbolIsPrefix)
                for (std::string_view symbol : symbolsOf(definition))
                    if (!symbol.empty()) actions.emplace(symbol, definition.action);
        return actions;
    }();
    for (const TurtleCommandDefinition& definition : kDefinitions) {
        const std::string_view prefix = definition.symbol;
        if (definition.symbolIsPrefix && name.size() > prefix.size() && name.starts_with(prefix))
            return {definition.action, name.substr(prefix.size())};
    }
    const auto found = exact.find(name);
    if (found == exact.end()) return {};
    const TurtleCommandDefinition& definition = turtleCommandDefinition(found->second);
    if ((definition.cpfgOnly && !cpfgModules) ||
        (definition.symbolNotInCpfg && cpfgModules && name == definition.symbol))
        return {};
    return {found->second, {}};
}

std::vector<TurtleCommand> turtleCommands(const SymbolTable& symbols, bool cpfgModules) {
    std::vector<TurtleCommand> commands;
    commands.reserve(symbols.size());
    for (const std::string& name : symbols.names) commands.push_back(turtleCommand(name, cpfgModules));
    return commands;
}

} // namespace lsys
