"""plantfield.render and plantfield.Renderer (docs/PYTHON.md "Rendering") on
the device the tools choose (lavapipe under ctest), against the pixels of the
plantfield tool: the same scene, size and times must give the same bytes."""
import json
import os
import subprocess
from pathlib import Path

import numpy
import pytest

import plantfield

DATA = Path(os.environ.get("PLANTFIELD_DATA_DIR", Path(__file__).resolve().parents[2] / "data"))
PLANTFIELD = os.environ.get("PLANTFIELD_BIN")
SIZE = (96, 54)
START, FPS, FRAMES = 0.5, 10.0, 3

needs_tool = pytest.mark.skipif(not PLANTFIELD, reason="PLANTFIELD_BIN (set by ctest) names the plantfield tool")


def run_plantfield(*args):
    result = subprocess.run([PLANTFIELD, *map(str, args)], capture_output=True, text=True, timeout=300)
    assert result.returncode == 0, result.stderr
    return result


@pytest.fixture(scope="module")
def tool_frames(tmp_path_factory):
    """plantfield --capture at START, and a --frames sequence from START (default scene)."""
    directory = tmp_path_factory.mktemp("plantfield")
    size = "%dx%d" % SIZE
    run_plantfield("--size", size, "--time", START, "--capture", directory / "capture.png")
    run_plantfield("--size", size, "--time", START, "--fps", FPS, "--frames", FRAMES, "--out-dir",
                   directory / "frames")
    return directory


def test_read_and_write_png_round_trip(tmp_path):
    image = numpy.zeros((3, 5, 4), dtype=numpy.uint8)
    image[..., 0] = numpy.arange(5, dtype=numpy.uint8) * 50
    image[1, 2] = (1, 2, 3, 4)
    plantfield.write_png(tmp_path / "image.png", image)
    assert numpy.array_equal(plantfield.read_png(tmp_path / "image.png"), image)
    with pytest.raises(ValueError, match="RGBA"):
        plantfield.write_png(tmp_path / "flat.png", numpy.zeros((3, 5), dtype=numpy.uint8))


@needs_tool
def test_render_equals_plantfield_capture(tool_frames):
    image = plantfield.render(size=SIZE, time=START, validation=True)
    assert image.shape == (SIZE[1], SIZE[0], 4) and image.dtype == numpy.uint8
    expected = plantfield.read_png(tool_frames / "capture.png")
    assert numpy.array_equal(image, expected), "%d bytes differ" % numpy.count_nonzero(image != expected)
    # A frame of a field, not a blank one: many colours.
    assert len(numpy.unique(image.reshape(-1, 4), axis=0)) > 100


@needs_tool
def test_renderer_sequence_equals_plantfield_frames(tool_frames):
    with plantfield.Renderer(size=SIZE, start=START, fps=FPS, validation=True) as renderer:
        # Frame 0 drawn by asking for frame 1 first would differ from the
        # tool's; asking in order, each frame continues the one before.
        frames = [renderer.frame(i) for i in range(FRAMES)]
        stats = renderer.stats()
        assert renderer.frames_drawn == FRAMES
        with pytest.raises(ValueError, match="frames go forward"):
            renderer.frame(1)
    for i, frame in enumerate(frames):
        expected = plantfield.read_png(tool_frames / "frames" / ("frame_%04d.png" % i))
        assert numpy.array_equal(frame, expected), "frame %d: %d bytes differ" % (i, numpy.count_nonzero(frame != expected))
    # The plants move: consecutive frames differ.
    assert not numpy.array_equal(frames[0], frames[FRAMES - 1])
    assert stats["size"] == list(SIZE) and stats["instances"] > 0
    assert stats["time"] == pytest.approx(START + (FRAMES - 1) / FPS)


def test_renderer_skips_ahead_to_the_same_frame():
    with plantfield.Renderer(DATA / "scenes" / "test_small.json", size=(64, 36), validation=True) as whole:
        frames = [whole.frame(i) for i in range(3)]
    with plantfield.Renderer(DATA / "scenes" / "test_small.json", size=(64, 36), validation=True) as skipping:
        assert numpy.array_equal(skipping.frame(2), frames[2])
        with pytest.raises(ValueError, match="numbered frames"):
            skipping.render(10.0)


def test_render_at_times_goes_forward():
    with plantfield.Renderer(DATA / "scenes" / "test_small.json", size=(64, 36), validation=True) as renderer:
        first = renderer.render(1.0)
        later = renderer.render(1.5)
        assert first.shape == later.shape == (36, 64, 4)
        with pytest.raises(ValueError, match="frames go forward"):
            renderer.render(1.0)
        assert renderer.device and renderer.scene.endswith("test_small.json")


def test_malformed_scene_names_file_line_and_column(tmp_path):
    scene = tmp_path / "broken.json"
    scene.write_text('{\n  "seed": 1,\n  "terrain": { "size": }\n}\n')
    with pytest.raises(plantfield.SceneError, match=r"broken\.json:3:\d+"):
        plantfield.render(scene, size=SIZE)
    assert issubclass(plantfield.SceneError, ValueError)


def test_missing_scene_is_named(tmp_path):
    with pytest.raises(plantfield.SceneError, match="no_such_scene.json"):
        plantfield.Renderer(tmp_path / "no_such_scene.json")


@pytest.mark.parametrize("size", [(0, 54), (96, 0), (-1, 54), (20000, 54), (96, 100000)])
def test_impossible_size_raises(size):
    with pytest.raises(ValueError, match="size"):
        plantfield.render(size=size)


@pytest.mark.parametrize("arguments, message", [
    ({"antialiasing": "ssaa"}, "unknown antialiasing"),
    ({"samples": 4}, "needs antialiasing='msaa'"),
    ({"antialiasing": "msaa", "samples": 3}, "samples must be 2, 4 or 8"),
    ({"time": -1.0}, "time must be"),
    ({"time": float("nan")}, "time must be"),
    ({"wind": 1000.0}, "wind speed"),
    ({"lod": 7}, "lod must be"),
])
def test_bad_arguments_raise(arguments, message):
    with pytest.raises(ValueError, match=message):
        plantfield.render(DATA / "scenes" / "test_small.json", size=SIZE, **arguments)


def test_missing_device_raises():
    with pytest.raises(RuntimeError, match="no such gpu"):
        plantfield.render(DATA / "scenes" / "test_small.json", size=SIZE, device="no such gpu")


def test_given_camera_replaces_the_path():
    scene = DATA / "scenes" / "test_small.json"
    above = ((0.0, 40.0, 0.1), (0.0, 0.0, 0.0), 50.0)
    with plantfield.Renderer(scene, size=(64, 36), validation=True) as renderer:
        on_path = renderer.render(0.0)
        from_above = renderer.render(0.0, camera=above)
    assert not numpy.array_equal(on_path, from_above)
    assert numpy.array_equal(plantfield.render(scene, size=(64, 36), camera=above), from_above)
    for bad in [((0, 1, 2),), ((0, 1, 2), (0, 1, 2)), ((0, 1), (0, 0, 0)), ((0, 9, 9), (0, 0, 0), 180.0)]:
        with pytest.raises(ValueError, match="camera must be"):
            plantfield.render(scene, size=(64, 36), camera=bad)


# write_png and read_png: the image must be uint8 (a float array was
# converted silently), the paths must be paths, and no writer replaces a
# folder or a file the session read (docs/PYTHON.md, the output rule).
@pytest.mark.parametrize("image, message", [
    (numpy.zeros((3, 5, 4), dtype=numpy.float32), "image must be a uint8 array"),
    (numpy.zeros((3, 5, 4), dtype=numpy.int64), "image must be a uint8 array"),
    ([[[0, 0, 0, 0]]], "image must be a numpy.ndarray"),
    (None, "image must be a numpy.ndarray"),
])
def test_write_png_takes_only_uint8_arrays(tmp_path, image, message):
    with pytest.raises(TypeError, match=message):
        plantfield.write_png(tmp_path / "typed.png", image)
    assert not (tmp_path / "typed.png").exists()


def test_png_paths_are_checked(tmp_path):
    image = numpy.zeros((2, 2, 4), dtype=numpy.uint8)
    with pytest.raises(TypeError, match="path"):
        plantfield.write_png(None, image)
    with pytest.raises(TypeError, match="path"):
        plantfield.read_png(None)
    (tmp_path / "folder.png").mkdir()
    with pytest.raises(ValueError, match="is a folder"):
        plantfield.write_png(tmp_path / "folder.png", image)
    with pytest.raises(ValueError, match="cannot read image"):
        plantfield.read_png(tmp_path / "folder.png")
    (tmp_path / "text.png").write_text("not a png")
    with pytest.raises(ValueError, match="cannot read image"):
        plantfield.read_png(tmp_path / "text.png")
    with pytest.raises(ValueError, match="RGBA"):
        plantfield.write_png(tmp_path / "strided.png", numpy.zeros((2, 2, 3), dtype=numpy.uint8))
    strided = numpy.arange(4 * 6 * 4, dtype=numpy.uint8).reshape(4, 6, 4)[:, ::2]
    plantfield.write_png(tmp_path / "strided.png", strided)
    assert numpy.array_equal(plantfield.read_png(tmp_path / "strided.png"), strided)


def test_writers_never_replace_what_the_session_read(tmp_path):
    # Copies only: were the rule broken, the repository's files would be replaced.
    scene = tmp_path / "scenes" / "scene.json"
    scene.parent.mkdir()
    scene.write_bytes((DATA / "scenes" / "test_small.json").read_bytes())
    (tmp_path / "plants").mkdir()
    for plant in ["stochastic_bush.lsys", "abop_1_24c.lsys"]:
        (tmp_path / "plants" / plant).write_bytes((DATA / "plants" / plant).read_bytes())
    image = plantfield.render(scene, size=(32, 18))
    (tmp_path / "link.png").symlink_to(scene)
    for path in [scene, tmp_path / "link.png", tmp_path / "plants" / "stochastic_bush.lsys"]:
        with pytest.raises(ValueError, match="never replaces a file the run reads"):
            plantfield.write_png(path, image)
    assert scene.read_bytes() == (DATA / "scenes" / "test_small.json").read_bytes()
    assert (tmp_path / "plants" / "stochastic_bush.lsys").read_bytes() == \
        (DATA / "plants" / "stochastic_bush.lsys").read_bytes()
    plantfield.write_png(tmp_path / "frame.png", image)
    plantfield.read_png(tmp_path / "frame.png")
    with pytest.raises(ValueError, match="never replaces a file the run reads"):
        plantfield.write_png(tmp_path / "frame.png", image)


@pytest.mark.parametrize("arguments, error, message", [
    ({"scene": 3}, TypeError, "scene must be"), ({"size": None}, TypeError, "size must be"), ({"size": (64,)}, TypeError, "size must be"),
    ({"size": (64.5, 36)}, TypeError, "size must be"), ({"time": None}, TypeError, "time must be"), ({"time": "0"}, TypeError, "time must be"),
    ({"time": float("inf")}, ValueError, "time must be"), ({"seed": -1}, TypeError, "seed must be"),
    ({"wind": "gale"}, TypeError, "wind must be"), ({"wind": (5.0, float("nan"))}, ValueError, "wind direction"),
    ({"wind": float("nan")}, ValueError, "wind speed"), ({"antialiasing": None}, TypeError, "antialiasing must be"),
    ({"samples": -4}, TypeError, "samples must be"), ({"shadows": None}, TypeError, "shadows must be"),
    ({"shadows": "no"}, TypeError, "shadows must be"), ({"lod": -1}, TypeError, "lod must be"),
    ({"validation": None}, TypeError, "validation must be"), ({"device": 3}, TypeError, "device must be"),
    ({"camera": 3}, TypeError, "camera must be"), ({"camera": "camera"}, TypeError, "camera must be"),
    ({"camera": ((0, 1, 2), (0, 0, 0), "wide")}, ValueError, "camera must be"),
])
def test_render_arguments_are_checked(arguments, error, message):
    with pytest.raises(error, match=message):
        plantfield.render(**{"scene": DATA / "scenes" / "test_small.json", "size": SIZE, **arguments})


@pytest.mark.parametrize("arguments, error, message", [
    ({"start": None}, TypeError, "start must be"), ({"start": -1.0}, ValueError, "start must be"),
    ({"fps": 0.0}, ValueError, "fps must be"), ({"fps": float("nan")}, ValueError, "fps must be"),
    ({"fps": "30"}, TypeError, "fps must be"),
])
def test_renderer_arguments_are_checked(arguments, error, message):
    with pytest.raises(error, match=message):
        plantfield.Renderer(DATA / "scenes" / "test_small.json", size=SIZE, **arguments)


def test_renderer_methods_check_their_arguments():
    with plantfield.Renderer(DATA / "scenes" / "test_small.json", size=(32, 18)) as renderer:
        for call, error in [(lambda: renderer.render(None), TypeError), (lambda: renderer.render(-1.0), ValueError),
                            (lambda: renderer.render(0.0, camera=5), TypeError),
                            (lambda: renderer.frame(None), TypeError), (lambda: renderer.frame(-1), TypeError)]:
            with pytest.raises(error):
                call()
    with pytest.raises(RuntimeError, match="closed"):
        renderer.render(0.0)
    with pytest.raises(RuntimeError, match="closed"):
        renderer.stats()
