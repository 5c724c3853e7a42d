#include "render_bindings.h"

#include "arguments.h"

#include "tools/data_dir.h"
#include "tools/field_options.h"

#include "engine/image/image.h"
#include "engine/offline/frame_stats_json.h"
#include "engine/offline/offline_renderer.h"
#include "engine/offline/scene_overrides.h"
#include "lsystem/common/error.h"
#include "lsystem/common/memory_budget.h"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <array>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <tuple>
#include <variant>

namespace py = pybind11;

namespace {

// Set in bindRender: plantfield.SceneError and plantfield.ValidationError
// (their C++ types are only tags).
struct ValidationErrorTag {};
py::handle sceneError;
py::handle validationError;

// The data folder as tools/data_dir.h finds it, from the module's own file:
// an installed module reads its prefix's share/plantfield/data.
std::string defaultScenePath() {
    const std::filesystem::path module = py::module_::import("plantfield").attr("__file__").cast<std::string>();
    // dataDirectoryFrom takes a file's path and looks beside its folder.
    return pf::dataDirectoryFrom(std::getenv("PLANTFIELD_DATA_DIR"), module, PLANTFIELD_INSTALL_DATA_RELATIVE,
                                 PLANTFIELD_DATA_DIR) +
           "/scenes/default.json"; // as the tools' defaultScenePath (tools/field_options.h)
}

// What plantfield.render and Renderer take besides the scene.
struct RenderArguments {
    std::tuple<int64_t, int64_t> size;
    std::optional<uint32_t> seed;
    std::optional<std::variant<float, std::tuple<float, float>>> wind;
    std::string antialiasing;
    std::optional<uint32_t> samples;
    bool shadows = true;
    std::optional<uint32_t> lod;
    bool validation = false;
    std::string device;
    double start = 0.0;
    double fps = 30.0;
};

// As plantfield --time takes it.
void checkTime(const char* name, double time) {
    if (!(time >= 0.0 && time <= pf::kMaxSceneTime))
        throw py::value_error(std::string(name) + " must be 0 to " + std::to_string(int(pf::kMaxSceneTime)) +
                              " scene seconds");
}

py::array_t<uint8_t> imageArray(const pf::RgbaImage& image) {
    py::array_t<uint8_t> array({py::ssize_t(image.height), py::ssize_t(image.width), py::ssize_t(4)});
    std::memcpy(array.mutable_data(), image.pixels.data(), image.pixels.size());
    return array;
}

py::array_t<uint8_t> readPng(const std::filesystem::path& path) {
    pf::RgbaImage image;
    try {
        py::gil_scoped_release release;
        const pyargs::SessionReads read;
        image = pf::readPng(path.string());
    } catch (const lsys::DerivationError&) { // past the memory budget: MemoryBudgetError
        throw;
    } catch (const std::runtime_error& error) { // not a PNG, or no file: a bad path
        throw py::value_error(error.what());
    }
    return imageArray(image);
}

// Only uint8 pixels: a float image converted silently would be clipped or
// wrapped into other colours.
void writePng(const std::filesystem::path& path, const py::object& image) {
    if (!py::isinstance<py::array>(image))
        throw py::type_error("image must be a numpy.ndarray of uint8, not " + pyargs::typeName(image));
    const py::array array = image.cast<py::array>();
    if (!array.dtype().is(py::dtype::of<uint8_t>()))
        throw py::type_error("image must be a uint8 array, not " + std::string(py::str(array.dtype())));
    if (array.ndim() != 3 || array.shape(2) != 4 || array.shape(0) < 1 || array.shape(1) < 1)
        throw py::value_error("write_png takes a (height, width, 4) uint8 RGBA array");
    pyargs::checkOutput(path, "path");
    const auto pixels = py::array_t<uint8_t, py::array::c_style>::ensure(array); // a contiguous copy if strided
    pf::RgbaImage rgba{uint32_t(array.shape(1)), uint32_t(array.shape(0)),
                       std::vector<uint8_t>(pixels.data(), pixels.data() + pixels.size())};
    py::gil_scoped_release release;
    pf::writePng(path.string(), rgba);
}

// camera=(position, target) or (position, target, fov_degrees), in metres
// and degrees, as a scene file's camera keyframes give them (docs/SCENE_FORMAT.md).
std::optional<pf::Camera> cameraArgument(const py::object& camera) {
    if (camera.is_none()) return std::nullopt;
    const char* expected = "camera must be (position, target) or (position, target, fov_degrees) with position "
                           "and target (x, y, z) apart and fov_degrees between 0 and 180";
    std::vector<py::object> parts;
    std::array<float, 3> position{}, target{};
    std::optional<float> fov;
    try {
        parts = camera.cast<std::vector<py::object>>();
    } catch (const py::cast_error&) { // not a sequence: a wrong type
        throw py::type_error(std::string(expected) + ", not " + pyargs::typeName(camera));
    }
    try {
        if (parts.size() != 2 && parts.size() != 3) throw py::value_error(expected);
        position = parts[0].cast<std::array<float, 3>>();
        target = parts[1].cast<std::array<float, 3>>();
        if (parts.size() == 3) fov = parts[2].cast<float>();
    } catch (const py::cast_error&) {
        throw py::value_error(expected);
    }
    pf::Camera c;
    c.position = {position[0], position[1], position[2]};
    c.target = {target[0], target[1], target[2]};
    if (fov) c.fovYDegrees = *fov;
    const auto finite3 = [](const glm::vec3& v) { return !glm::any(glm::isnan(v)) && !glm::any(glm::isinf(v)); };
    const bool finite = finite3(c.position) && finite3(c.target);
    if (!finite || c.position == c.target || !(c.fovYDegrees > 0.0f && c.fovYDegrees < 180.0f))
        throw py::value_error(expected);
    return c;
}

// The field's notes and its species' L-system warnings, which plantfield
// prints on stderr, as Python warnings.
void warnAbout(const pf::FieldContent& content) {
    for (const std::string& text : {content.note, content.models.warnings})
        if (!text.empty() && PyErr_WarnEx(PyExc_UserWarning, text.c_str(), 1) != 0) throw py::error_already_set();
}

pf::SceneOverrides sceneOverrides(const RenderArguments& a) {
    pf::SceneOverrides overrides;
    overrides.seed = a.seed;
    if (a.wind) {
        float speed = 0.0f;
        if (const auto* pair = std::get_if<std::tuple<float, float>>(&*a.wind)) {
            speed = std::get<0>(*pair);
            const float direction = std::get<1>(*pair);
            if (!std::isfinite(direction)) throw py::value_error("wind direction must be a finite number of degrees");
            overrides.windDirectionDegrees = direction;
        } else {
            speed = std::get<float>(*a.wind);
        }
        // The range plantfield --wind accepts (tools/plantfield/options.h parseWind).
        if (!(speed >= 0.0f && speed <= 100.0f)) throw py::value_error("wind speed must be 0 to 100 m/s");
        overrides.windSpeed = speed;
    }
    return overrides;
}

pf::OfflineSettings offlineSettings(const RenderArguments& a) {
    pf::OfflineSettings s;
    const auto [width, height] = a.size;
    // The largest side plantfield --size takes; the device may allow less (then RuntimeError).
    if (width < 1 || height < 1 || width > 16384 || height > 16384)
        throw py::value_error("size must be (width, height) of 1 to 16384 pixels each, not (" + std::to_string(width) +
                              ", " + std::to_string(height) + ")");
    s.size = {uint32_t(width), uint32_t(height)};
    const std::optional<pf::AntialiasMethod> method = pf::antialiasMethodNamed(a.antialiasing);
    if (!method) throw py::value_error("unknown antialiasing '" + a.antialiasing + "' (expected fxaa, msaa or none)");
    s.render.antialiasing.method = *method;
    if (a.samples) {
        if (*method != pf::AntialiasMethod::msaa)
            throw py::value_error("samples is the MSAA sample count: it needs antialiasing='msaa'");
        // As plantfield --samples: lowered to what the device supports.
        if (*a.samples != 2 && *a.samples != 4 && *a.samples != 8) throw py::value_error("samples must be 2, 4 or 8");
        s.render.antialiasing.msaaSamples = *a.samples;
    }
    s.render.shadows = a.shadows ? pf::SunShadows::map : pf::SunShadows::none;
    if (a.lod && *a.lod >= LOD_COUNT) throw py::value_error("lod must be 0 to " + std::to_string(LOD_COUNT - 1));
    s.forcedLod = a.lod;
    s.gpu.validation = a.validation;
    s.gpu.echoValidation = false; // raised as ValidationError instead
    s.gpu.deviceName = a.device;
    s.gpu.hostMemoryLimit = lsys::machineMemoryBudget().limitBytes; // as the tools' default --memory-budget
    checkTime("start", a.start);
    // The range of plantfield --fps.
    if (!(a.fps >= 0.1 && a.fps <= 1000.0)) throw py::value_error("fps must be 0.1 to 1000 frames a scene second");
    s.start = a.start;
    s.fps = a.fps;
    return s;
}

// A scene's field and a renderer drawing it; the device lives as long as it.
class PyRenderer {
public:
    PyRenderer(const std::optional<std::filesystem::path>& scene, const RenderArguments& arguments)
        : scene_(scene ? scene->string() : defaultScenePath()) {
        const pf::SceneOverrides overrides = sceneOverrides(arguments);
        pf::OfflineSettings settings = offlineSettings(arguments);
        pf::FieldContent content;
        {
            py::gil_scoped_release release;
            const pyargs::SessionReads read; // the scene's files, which no writer of the session replaces
            content = pf::buildFieldContent(pf::loadScene(scene_, overrides));
        }
        warnAbout(content);
        {
            py::gil_scoped_release release;
            renderer_ = std::make_unique<pf::OfflineRenderer>(std::move(content), std::move(settings));
        }
        checkValidation();
    }

    py::array_t<uint8_t> render(double time, const py::object& camera) {
        checkTime("time", time);
        const std::optional<pf::Camera> view = cameraArgument(camera);
        return image([&](pf::OfflineRenderer& r) { return r.render(time, view); });
    }

    py::array_t<uint8_t> frame(uint32_t index) {
        return image([&](pf::OfflineRenderer& r) { return r.frame(index); });
    }

    py::object stats() {
        const std::string json = [&] {
            std::lock_guard lock(mutex_);
            return pf::frameStatsJson(open(), scene_);
        }();
        return py::module_::import("json").attr("loads")(json);
    }

    // Destroys the device (the validation layer reports leaks then) and
    // raises ValidationError when the layer said anything.
    void close() {
        std::unique_ptr<pf::OfflineRenderer> closing;
        {
            std::lock_guard lock(mutex_);
            closing = std::move(renderer_);
        }
        if (!closing) return;
        const std::unique_ptr<pf::ValidationLog> log = closing->takeValidationLog();
        {
            py::gil_scoped_release release;
            closing.reset();
        }
        raiseValidation(log.get());
    }

    const std::string& scene() const { return scene_; }
    std::tuple<uint32_t, uint32_t> size() {
        const VkExtent2D size = open().size();
        return {size.width, size.height};
    }
    std::string device() { return open().context().properties.deviceName; }
    uint32_t framesDrawn() { return open().framesDrawn(); }

private:
    pf::OfflineRenderer& open() {
        if (!renderer_) throw std::logic_error("the renderer is closed");
        return *renderer_;
    }

    template <class Draw>
    py::array_t<uint8_t> image(const Draw& draw) {
        pf::RgbaImage frame;
        {
            py::gil_scoped_release release;
            std::lock_guard lock(mutex_);
            frame = draw(open());
        }
        checkValidation();
        return imageArray(frame);
    }

    void checkValidation() {
        if (renderer_) raiseValidation(renderer_->context().validationLog.get());
    }

    static void raiseValidation(pf::ValidationLog* log) {
        if (!log) return;
        const std::vector<std::string> messages = log->snapshot();
        if (messages.empty()) return;
        log->clear();
        py::object error =
            validationError(std::to_string(messages.size()) + " validation message(s), first: " + messages.front());
        error.attr("messages") = messages;
        PyErr_SetObject(validationError.ptr(), error.ptr());
        throw py::error_already_set();
    }

    std::string scene_;
    std::mutex mutex_; // one frame at a time: the GIL is released while drawing
    std::unique_ptr<pf::OfflineRenderer> renderer_;
};

} // namespace

void bindRender(py::module_& m) {
    sceneError = py::exception<pf::SceneError>(m, "SceneError", PyExc_ValueError).ptr();
    validationError = py::exception<ValidationErrorTag>(m, "ValidationError", PyExc_RuntimeError).ptr();
    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) std::rethrow_exception(p);
        } catch (const pf::SceneError& e) {
            PyErr_SetString(sceneError.ptr(), e.what());
        }
    });

    const auto arguments = [](std::tuple<int64_t, int64_t> size, std::optional<uint32_t> seed,
                              std::optional<std::variant<float, std::tuple<float, float>>> wind,
                              std::string antialiasing, std::optional<uint32_t> samples, bool shadows,
                              std::optional<uint32_t> lod, bool validation, std::optional<std::string> device) {
        RenderArguments a;
        a.size = size;
        a.seed = seed;
        a.wind = wind;
        a.antialiasing = std::move(antialiasing);
        a.samples = samples;
        a.shadows = shadows;
        a.lod = lod;
        a.validation = validation;
        a.device = device.value_or("");
        return a;
    };

    py::class_<PyRenderer, std::shared_ptr<PyRenderer>> renderer(
        m, "Renderer", "A scene's field on a Vulkan device, rendering frame after frame (docs/PYTHON.md)");
    pyargs::defCheckedInit(
        renderer, "Renderer",
        [arguments](std::optional<std::filesystem::path> scene, std::tuple<int64_t, int64_t> size, double start,
                    double fps, std::optional<uint32_t> seed,
                    std::optional<std::variant<float, std::tuple<float, float>>> wind, std::string antialiasing,
                    std::optional<uint32_t> samples, bool shadows, std::optional<uint32_t> lod, bool validation,
                    std::optional<std::string> device) {
            RenderArguments a =
                arguments(size, seed, wind, std::move(antialiasing), samples, shadows, lod, validation, device);
            a.start = start;
            a.fps = fps;
            return std::make_shared<PyRenderer>(scene, a);
        },
        py::arg("scene") = py::none(), py::arg("size") = std::make_tuple(int64_t(1280), int64_t(720)),
        py::arg("start") = 0.0, py::arg("fps") = 30.0, py::arg("seed") = py::none(), py::arg("wind") = py::none(),
        py::arg("antialiasing") = "fxaa", py::arg("samples") = py::none(), py::arg("shadows").noconvert() = true,
        py::arg("lod") = py::none(), py::arg("validation").noconvert() = false, py::arg("device") = py::none());
    pyargs::defChecked(renderer, "render", &PyRenderer::render, py::arg("time"), py::arg("camera") = py::none(),
                       "The frame at scene time `time` (not before the last frame's) as a (height, width, 4) uint8 "
                       "RGBA array; camera=(position, target[, fov_degrees]) in place of the scene's camera path");
    pyargs::defChecked(renderer, "frame", &PyRenderer::frame, py::arg("index"),
                       "Frame `index` of the sequence at start + index / fps, as plantfield --frames writes "
                       "frame_INDEX.png; frames go forward");
    renderer.def("stats", &PyRenderer::stats, "The last frame's statistics, as plantfield --stats prints them")
        .def("close", &PyRenderer::close, "Releases the device; raises ValidationError for any validation message")
        .def(
            "__enter__", [](PyRenderer& r) -> PyRenderer& { return r; }, py::return_value_policy::reference)
        .def("__exit__", [](PyRenderer& r, py::object, py::object, py::object) { r.close(); })
        .def_property_readonly("scene", &PyRenderer::scene)
        .def_property_readonly("size", &PyRenderer::size)
        .def_property_readonly("device", &PyRenderer::device)
        .def_property_readonly("frames_drawn", &PyRenderer::framesDrawn);

    pyargs::defChecked(
        m, "render",
        [arguments](std::optional<std::filesystem::path> scene, std::tuple<int64_t, int64_t> size, double time,
                    std::optional<uint32_t> seed, std::optional<std::variant<float, std::tuple<float, float>>> wind,
                    std::string antialiasing, std::optional<uint32_t> samples, bool shadows,
                    std::optional<uint32_t> lod, bool validation, std::optional<std::string> device,
                    const py::object& camera) {
            checkTime("time", time); // before the field is built
            cameraArgument(camera);
            PyRenderer renderer(
                scene, arguments(size, seed, wind, std::move(antialiasing), samples, shadows, lod, validation, device));
            py::array_t<uint8_t> image = renderer.render(time, camera);
            renderer.close();
            return image;
        },
        py::arg("scene") = py::none(), py::arg("size") = std::make_tuple(int64_t(1280), int64_t(720)),
        py::arg("time") = 0.0, py::arg("seed") = py::none(), py::arg("wind") = py::none(),
        py::arg("antialiasing") = "fxaa", py::arg("samples") = py::none(), py::arg("shadows").noconvert() = true,
        py::arg("lod") = py::none(), py::arg("validation").noconvert() = false, py::arg("device") = py::none(),
        py::arg("camera") = py::none(),
        "One frame of the scene (default: the default scene) at scene time `time`, as plantfield --capture "
        "renders it: a (height, width, 4) uint8 RGBA array; camera=(position, target[, fov_degrees]) in place of "
        "the scene's camera path");

    pyargs::defChecked(m, "read_png", &readPng, py::arg("path"), "A PNG file as a (height, width, 4) uint8 RGBA array");
    pyargs::defChecked(m, "write_png", &writePng, py::arg("path"), py::arg("image"),
                       "Writes a (height, width, 4) uint8 RGBA array as a PNG file (whole or not at all)");
}
