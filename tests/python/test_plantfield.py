"""The Python module plantfield (tools/python, docs/PYTHON.md)."""
import json
import os
import struct
from pathlib import Path

import pytest

import plantfield

DATA = Path(os.environ.get("PLANTFIELD_DATA_DIR", Path(__file__).resolve().parents[2] / "data"))
PLANTS = DATA / "plants"


def test_version():
    assert plantfield.__version__.count(".") >= 1


# The counts tests/lsystem/cli_test.sh and tests/install pin for lsys derive.
def test_derive_fractal_bush():
    grammar = plantfield.load(PLANTS / "fractal_bush.lsys")
    derived = plantfield.derive(grammar, steps=3)
    assert len(derived) == 1388
    assert sum(derived.counts().values()) == 1388
    assert len(str(derived)) > 0


def test_derive_koch_curve():
    grammar = plantfield.load(str(PLANTS / "koch_curve.lsys"))
    derived = plantfield.derive(grammar, 4)
    assert len(derived) == 1249
    counts = derived.counts()
    assert counts["F"] > 0 and "+" in counts
    assert derived.to_cpfg().count("F") == counts["F"]


def test_parse_text_and_counts():
    grammar = plantfield.parse("derivation length: 5\nAxiom: A\nA --> A B\nB --> A\n")
    derived = plantfield.derive(grammar)
    assert derived.counts() == {"A": 8, "B": 5}
    assert str(derived).replace(" ", "").startswith("ABAAB")


def test_parse_error_located():
    with pytest.raises(plantfield.LsystemError) as info:
        plantfield.parse("Axiom: A\nA --> B(\n", file="bad.lsys")
    diagnostics = info.value.diagnostics
    assert diagnostics, "at least one diagnostic"
    file, line, column, message = diagnostics[0]
    assert file == "bad.lsys" and line == 2 and column > 0 and message
    assert "bad.lsys:2:" in str(info.value)


def test_load_missing_file():
    with pytest.raises(plantfield.LsystemError) as info:
        plantfield.load(PLANTS / "no_such_plant.lsys")
    assert "no_such_plant.lsys" in str(info.value)


def test_unknown_dialect():
    with pytest.raises(ValueError, match="unknown dialect"):
        plantfield.parse("Axiom: A\n", dialect="klingon")


def test_module_budget():
    grammar = plantfield.load(PLANTS / "fractal_bush.lsys")
    with pytest.raises(plantfield.ModuleBudgetError, match="module budget exceeded"):
        plantfield.derive(grammar, steps=7, max_modules=100000)
    assert issubclass(plantfield.ModuleBudgetError, plantfield.DerivationError)


def test_instance_stats():
    stats = plantfield.instance_stats(plantfield.load(PLANTS / "fractal_bush.lsys"), steps=9)
    assert set(stats) == {"primitives", "joints", "nodes", "objects", "instances", "compression",
                          "bytes_graph", "bytes_flat"}
    # As tests/lsystem/cli_test.sh pins `lsys instance -n 9 --json`.
    assert (stats["primitives"], stats["joints"], stats["nodes"], stats["objects"], stats["instances"]) == \
        (134217728, 134217728, 9, 9, 72)


def read_glb(path):
    data = Path(path).read_bytes()
    magic, version, length = struct.unpack_from("<4sII", data, 0)
    assert magic == b"glTF" and version == 2 and length == len(data)
    chunk_length, chunk_type = struct.unpack_from("<II", data, 12)
    assert chunk_type == 0x4E4F534A  # "JSON"
    return json.loads(data[20:20 + chunk_length])


@pytest.fixture
def output_dir(tmp_path):
    directory = os.environ.get("PLANTFIELD_TEST_OUTPUT_DIR")
    if not directory:
        return tmp_path
    Path(directory).mkdir(parents=True, exist_ok=True)
    return Path(directory)


def test_export_glb(output_dir):
    grammar = plantfield.load(PLANTS / "fractal_bush.lsys")
    path = output_dir / "fractal_bush.glb"
    plantfield.export(grammar, path, steps=3, sides=6)
    assert read_glb(path)["meshes"]


def test_export_instanced_glb(output_dir):
    path = output_dir / "fractal_bush_instanced.glb"
    plantfield.export(plantfield.load(PLANTS / "fractal_bush.lsys"), str(path), steps=3, instanced=True)
    document = read_glb(path)
    assert document["meshes"] and document["nodes"]


def vertex_count(document):
    return sum(document["accessors"][primitive["attributes"]["POSITION"]]["count"]
               for mesh in document["meshes"] for primitive in mesh["primitives"])


def test_export_geometry(output_dir):
    # The drawn form (the default) draws the spruce's needles as ribbons, 4 vertices a needle
    # where the turtle's frusta have 36: far fewer vertices.
    spruce = plantfield.load(PLANTS / "spruce.lsys")
    counts = {}
    for geometry in ("drawn", "frusta", "tubes"):
        path = output_dir / f"spruce_{geometry}.glb"
        plantfield.export(spruce, path, geometry=geometry)
        counts[geometry] = vertex_count(read_glb(path))
    plantfield.export(spruce, output_dir / "spruce_default.glb")
    assert vertex_count(read_glb(output_dir / "spruce_default.glb")) == counts["drawn"]
    assert counts["drawn"] < counts["tubes"] < counts["frusta"]
    with pytest.raises(ValueError, match="geometry"):
        plantfield.export(spruce, output_dir / "spruce_bad.glb", geometry="cones")


def test_export_bad_extension(output_dir):
    with pytest.raises(RuntimeError):
        plantfield.export(plantfield.parse("Axiom: F\n"), output_dir / "plant.txt")


# Tankard 2001's Figure 3 matrix, from the tree tests/ramification pins by hand.
def test_ramify_gives_figure_three():
    figure3 = Path(__file__).resolve().parents[1] / "ramification" / "data" / "figure3.lsys"
    matrix = plantfield.ramify(plantfield.load(figure3))
    assert matrix == {"orders": 3, "a": [8, 5, 2], "p": [[1.0], [0.6, 0.4], [0.5, 0.0, 0.5]]}


def test_ramified_tree_is_a_plant_of_its_matrix():
    oak = DATA / "ramified" / "oak.ram.json"
    tree = plantfield.ramified_tree(oak, seed=3)
    assert str(plantfield.derive(tree)) == str(plantfield.derive(plantfield.ramified_tree(oak, seed=3)))
    assert str(plantfield.derive(tree)) != str(plantfield.derive(plantfield.ramified_tree(oak, seed=4)))
    matrix = plantfield.ramify(tree)
    assert matrix["orders"] == 7
    for row in matrix["p"]:
        assert sum(row) == pytest.approx(1.0)


def test_ramified_tree_errors(tmp_path):
    bad = tmp_path / "bad.ram.json"
    bad.write_text('{\n  "p": [[1], [0.5, 0.5]],\n  "twst": 3\n}\n')
    with pytest.raises(plantfield.LsystemError) as error:
        plantfield.ramified_tree(bad)
    assert error.value.diagnostics[0][1:3] == (3, 3)
    assert error.value.diagnostics[0][3] == '/twst is an unknown key; did you mean "twist"?'
    with pytest.raises(plantfield.RamificationBudgetError):
        plantfield.ramified_tree(DATA / "ramified" / "oak.ram.json", max_branches=10)


# Every function's arguments: a wrong type is a TypeError naming the argument
# and what it must be (pybind11's own would list the whole signature), a value
# out of range a ValueError, never a crash (derive(None) was a null pointer).
def export_to_nowhere(grammar, **arguments):
    plantfield.export(grammar, "never_written.glb", **arguments)


GRAMMAR_FUNCTIONS = [plantfield.derive, plantfield.instance_stats, plantfield.ramify, export_to_nowhere]


@pytest.mark.parametrize("function", GRAMMAR_FUNCTIONS)
@pytest.mark.parametrize("bad", [None, 3, "fractal_bush.lsys", plantfield])
def test_grammar_must_be_a_grammar(function, bad):
    with pytest.raises(TypeError, match="grammar must be a plantfield.Grammar"):
        function(bad)
    assert not Path("never_written.glb").exists()


@pytest.mark.parametrize("function", GRAMMAR_FUNCTIONS)
@pytest.mark.parametrize("arguments, error", [
    ({"steps": -1}, ValueError), ({"steps": 10**7}, ValueError), ({"steps": 2**40}, TypeError),
    ({"steps": "3"}, TypeError), ({"seed": -1}, TypeError), ({"seed": 1.5}, TypeError),
    ({"max_modules": None}, TypeError), ({"max_modules": -1}, TypeError),
])
def test_derivation_arguments_are_checked(function, arguments, error):
    grammar = plantfield.parse("Axiom: F\nF --> F F\n")
    name = next(iter(arguments))
    with pytest.raises(error, match="steps must be 0 to 1000000" if error is ValueError else f"\\(\\): {name} must be"):
        function(grammar, **arguments)


def test_type_errors_say_what_the_argument_must_be_and_was():
    grammar = plantfield.parse("Axiom: F\n")
    with pytest.raises(TypeError, match=r"^derive\(\): steps must be None or an integer -2147483648 to 2147483647, "
                                        r"not str$"):
        plantfield.derive(grammar, steps="3")
    with pytest.raises(TypeError, match=r"^derive\(\): seed must be None or an integer 0 to 18446744073709551615, "
                                        r"not -1$"):
        plantfield.derive(grammar, seed=-1)
    with pytest.raises(TypeError, match=r"^derive\(\) got an unexpected keyword argument 'stpes'$"):
        plantfield.derive(grammar, stpes=3)
    with pytest.raises(TypeError, match=r"^derive\(\) missing required argument 'grammar'$"):
        plantfield.derive()
    with pytest.raises(TypeError, match=r"^derive\(\) takes at most 4 arguments \(5 given\)$"):
        plantfield.derive(grammar, 1, 2, 3, 4)
    with pytest.raises(TypeError, match=r"^derive\(\) got multiple values for argument 'steps'$"):
        plantfield.derive(grammar, 1, steps=2)
    # Conversions pybind11 makes still happen: an integer for a float, a str path.
    assert len(plantfield.derive(grammar, steps=0)) == 1
    assert plantfield.load(str(PLANTS / "koch_curve.lsys")).file.endswith("koch_curve.lsys")


def test_help_shows_the_typed_signature():
    assert plantfield.derive.__doc__.startswith("derive(grammar: object, steps: Optional[int] = None")
    assert "Overloaded" not in plantfield.derive.__doc__
    assert "*args" not in plantfield.export.__doc__


@pytest.mark.parametrize("call, error, message", [
    (lambda: plantfield.load(None), TypeError, "path must be"),
    (lambda: plantfield.load(3), TypeError, "path must be"),
    (lambda: plantfield.load(PLANTS / "koch_curve.lsys", defines=None), TypeError, "defines must be"),
    (lambda: plantfield.load(PLANTS / "koch_curve.lsys", defines={"x": float("nan")}), ValueError, "finite"),
    (lambda: plantfield.load(PLANTS / "koch_curve.lsys", dialect=3), TypeError, "dialect must be"),
    (lambda: plantfield.parse(None), TypeError, "text must be"),
    (lambda: plantfield.parse("Axiom: F\n", file=None), TypeError, "file must be"),
    (lambda: plantfield.parse("Axiom: F\n", defines={"x": float("inf")}), ValueError, "finite"),
    (lambda: plantfield.parse("Axiom: F\n", defines={3: 1.0}), TypeError, "defines must be"),
    (lambda: plantfield.ramified_tree(None), TypeError, "path must be"),
    (lambda: plantfield.ramified_tree(DATA / "ramified" / "oak.ram.json", max_branches=0), ValueError, "max_branches"),
    (lambda: plantfield.ramified_tree(DATA / "ramified" / "oak.ram.json", max_branches=2**41), ValueError,
     "max_branches"),
    (lambda: plantfield.ramified_tree(DATA / "ramified" / "oak.ram.json", seed=-1), TypeError, "seed must be"),
])
def test_loading_arguments_are_checked(call, error, message):
    with pytest.raises(error, match=message):
        call()


@pytest.mark.parametrize("arguments, error, message", [
    ({"path": None}, TypeError, "path must be"), ({"path": 3}, TypeError, "path must be"),
    ({"sides": 2}, ValueError, "sides"), ({"sides": -8}, TypeError, "sides must be"),
    ({"instanced": None}, TypeError, "instanced must be"), ({"skeleton": "yes"}, TypeError, "skeleton must be"),
    ({"geometry": None}, TypeError, "geometry must be"), ({"geometry": "cones"}, ValueError, "geometry"),
])
def test_export_arguments_are_checked(output_dir, arguments, error, message):
    arguments = {"path": output_dir / "checked.glb", **arguments}
    with pytest.raises(error, match=message):
        plantfield.export(plantfield.parse("Axiom: F\n"), **arguments)


# The output rule (docs/PYTHON.md): no writer replaces a folder or a file the
# session has read, by any name.
def test_export_never_replaces_an_input(tmp_path):
    plant = tmp_path / "bush.lsys"
    plant.write_bytes((PLANTS / "fractal_bush.lsys").read_bytes())
    grammar = plantfield.load(plant)
    mtl_plant = tmp_path / "twin.mtl"
    mtl_plant.write_bytes(plant.read_bytes())
    twin = plantfield.load(mtl_plant)
    (tmp_path / "link.glb").symlink_to(plant)
    (tmp_path / "folder.glb").mkdir()
    for path, read in [(plant, grammar), (tmp_path / "link.glb", grammar), (tmp_path / "twin.obj", twin)]:
        with pytest.raises(ValueError, match="never replaces a file the run reads"):
            plantfield.export(read, path, steps=2)
    with pytest.raises(ValueError, match="is a folder"):
        plantfield.export(grammar, tmp_path / "folder.glb", steps=2)
    assert plant.read_bytes() == (PLANTS / "fractal_bush.lsys").read_bytes()
    assert mtl_plant.read_bytes() == plant.read_bytes()
    assert not (tmp_path / "twin.obj").exists()
    plantfield.export(grammar, tmp_path / "bush.obj", steps=2)  # its own .mtl is no input
    assert (tmp_path / "bush.mtl").exists()


def test_ramified_tree_file_is_an_input(tmp_path):
    oak = tmp_path / "oak.ram.json"
    oak.write_bytes((DATA / "ramified" / "oak.ram.json").read_bytes())
    tree = plantfield.ramified_tree(oak, seed=2)
    with pytest.raises(ValueError, match="never replaces a file the run reads"):
        plantfield.export(tree, oak)
    assert oak.read_bytes() == (DATA / "ramified" / "oak.ram.json").read_bytes()
