"""The package and `inertia-lab props --json` give the same object for the same file, and the
arrays of a file give its numbers and warnings."""

import json
import math
from pathlib import Path

import numpy as np
import pytest

import inertialab as il
from conftest import ASSETS, REAL, props_binary, props_json

# Defects, one file each: the words and numbers of each warning must be the CLI's.
CUBE_V = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
CUBE_F = ["1 4 3 2", "5 6 7 8", "1 2 6 5", "2 3 7 6", "3 4 8 7", "4 1 5 8"]
DEFECTS = {
    "holes.obj": CUBE_V + "".join(f"f {f}\n" for f in CUBE_F[1:]),
    "flipped.obj": CUBE_V + "".join(f"f {' '.join(reversed(f.split()))}\n" for f in CUBE_F),
    "duplicate.obj": CUBE_V + "".join(f"f {f}\n" for f in CUBE_F + CUBE_F[:2]),
    "two_cubes.obj": CUBE_V
    + "".join(f"v {x + 0.5} {y} {z}\n" for x, y, z in [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)])
    + "".join(f"f {f}\n" for f in CUBE_F)
    + "".join("f " + " ".join(str(int(i) + 8) for i in f.split()) + "\n" for f in CUBE_F),
}


def fixtures():
    files = sorted(ASSETS.glob("*.obj")) + sorted(ASSETS.glob("*.stl")) + sorted(ASSETS.glob("*.toml"))
    return files + sorted(REAL.glob("*.stl"))


@pytest.mark.parametrize("path", fixtures(), ids=lambda p: p.name)
def test_every_fixture_is_props_json(path):
    assert il.analyze_file(path).to_dict() == props_json("test_every_fixture_is_props_json", path)


@pytest.mark.parametrize("name", sorted(DEFECTS))
def test_defects_are_props_json(name, tmp_path):
    path = tmp_path / name
    path.write_text(DEFECTS[name])
    expected = props_json("test_defects_are_props_json", path)
    assert expected["warnings"], "each of these files has a defect"
    assert il.analyze_file(path).to_dict() == expected


def obj_arrays(path: Path):
    v, f = [], []
    for line in path.read_text().splitlines():
        words = line.split()
        if words and words[0] == "v":
            v.append([float(x) for x in words[1:4]])
        elif words and words[0] == "f":
            f.append([int(w.split("/")[0]) - 1 for w in words[1:]])
    return np.array(v), f


@pytest.mark.parametrize("name", sorted(DEFECTS))
def test_arrays_give_the_files_numbers(name, tmp_path):
    path = tmp_path / name
    path.write_text(DEFECTS[name])
    from_file = il.analyze_file(path).to_dict()
    v, f = obj_arrays(path)
    from_arrays = il.mass_properties(v, f).to_dict()
    for key in ("mass", "volume", "center_of_mass", "inertia_com", "principal_moments", "mesh", "shells"):
        assert from_arrays[key] == from_file[key], key
    strip = lambda ws: [{k: w[k] for k in ("code", "count", "faces", "effect_on_mass")} for w in ws]
    assert strip(from_arrays["warnings"]) == strip(from_file["warnings"])
    assert from_arrays["file"] is None and from_file["file"] == str(path)


def test_options_are_props_options(tmp_path):
    path = tmp_path / "holes.obj"
    path.write_text(DEFECTS["holes.obj"])
    name = "test_options_are_props_options"
    assert il.analyze_file(path, density=7850.0).to_dict() == props_json(name, path, "--density", "7850")
    assert il.analyze_file(path, mass=2.0, method="shell").to_dict() == props_json(
        name, path, "--mass", "2", "--method", "shell"
    )
    with pytest.raises(il.MeshError) as e:
        il.analyze_file(path, repairs=il.Repairs(holes="refuse"))
    assert e.value.kind == "open_mesh" and str(path) in str(e.value)


def test_file_errors(tmp_path):
    with pytest.raises(FileNotFoundError, match="missing.obj"):
        il.analyze_file(tmp_path / "missing.obj")
    bad = tmp_path / "bad.obj"
    bad.write_text("v 0 0 0\nv 1 0 x\nf 1 2 3\n")
    with pytest.raises(il.MeshError, match="line 2") as e:
        il.analyze_file(bad)
    assert e.value.kind == "malformed"
    other = tmp_path / "notes.txt"
    other.write_text("hello")
    with pytest.raises(il.MeshError) as e:
        il.analyze_file(other)
    assert e.value.kind == "unsupported_format"


def test_a_ply_file_is_read_as_props_reads_it(tmp_path):
    # The mesh-format table is the native module's: PLY is searched for and read like OBJ.
    assert il.MESH_EXTENSIONS == (
        ".obj", ".stl", ".ply", ".off", ".glb", ".gltf", ".msh", ".dae", ".3mf", ".toml"
    )
    corners = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]
    quads = [(0, 3, 2, 1), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7)]
    path = tmp_path / "box.ply"
    path.write_text(
        "ply\nformat ascii 1.0\nelement vertex 8\nproperty double x\nproperty double y\n"
        "property double z\nelement face 6\nproperty list uchar int vertex_indices\nend_header\n"
        + "".join(f"{2 * x} {3 * y} {5 * z}\n" for x, y, z in corners)
        + "".join("4 %d %d %d %d\n" % q for q in quads)
    )
    result = il.analyze_file(path, density=2.0)
    assert result.to_dict() == props_json("test_a_ply_file_is_read_as_props_reads_it", path, "--density", "2")
    # A 2 × 3 × 5 box of density 2: mass 60, I₁ = m(b² + c²)/12 about its centre.
    assert math.isclose(result.mass, 60.0, rel_tol=1e-15)
    assert math.isclose(result.principal_moments[0], 60.0 * (4 + 9) / 12, rel_tol=1e-14)


def test_a_collada_file_is_read_in_metres_and_known_by_its_content(tmp_path):
    # A 20 × 30 × 50 cm box in a COLLADA file of centimetres: 0.03 m³; its bytes named wrongly
    # in a table are known by their <COLLADA root, as they are without a name.
    import pyarrow as pa
    corners = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]
    quads = [(0, 3, 2, 1), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7)]
    positions = " ".join(f"{20 * x} {30 * y} {50 * z}" for x, y, z in corners)
    text = (
        '<?xml version="1.0"?><COLLADA version="1.4.1"><asset><unit meter="0.01"/>'
        "<up_axis>Z_UP</up_axis></asset><library_geometries><geometry id=\"g\"><mesh>"
        f'<source id="p"><float_array id="a" count="24">{positions}</float_array>'
        '<technique_common><accessor source="#a" count="8" stride="3"/></technique_common>'
        '</source><vertices id="v"><input semantic="POSITION" source="#p"/></vertices>'
        '<polylist count="6"><input semantic="VERTEX" source="#v" offset="0"/>'
        "<vcount>4 4 4 4 4 4</vcount><p>" + " ".join("%d %d %d %d" % q for q in quads)
        + '</p></polylist></mesh></geometry></library_geometries><library_visual_scenes>'
        '<visual_scene id="s"><node name="box"><instance_geometry url="#g"/></node>'
        '</visual_scene></library_visual_scenes><scene><instance_visual_scene url="#s"/></scene>'
        "</COLLADA>"
    )
    path = tmp_path / "box.dae"
    path.write_text(text)
    result = il.analyze_file(path)
    assert result.to_dict() == props_json(
        "test_a_collada_file_is_read_in_metres_and_known_by_its_content", path
    )
    assert math.isclose(result.volume, 0.2 * 0.3 * 0.5, rel_tol=1e-14)
    table = il.measure_table(
        pa.table({"path": ["box.bin"], "bytes": [text.encode()]}), bytes_col="bytes"
    )
    assert table.column("volume").to_pylist() == [result.volume]


def test_exports_are_the_clis(tmp_path):
    import subprocess

    path = ASSETS / "t_handle.obj"
    r = il.analyze_file(path, density=2700.0)
    binary = props_binary("test_exports_are_the_clis")
    for fmt, text in (("mjcf", r.to_mjcf()), ("urdf", r.to_urdf()), ("sdf", r.export("sdf"))):
        cli = subprocess.run(
            [binary, "export", str(path), "--format", fmt, "--density", "2700"],
            check=True, capture_output=True, text=True,
        ).stdout
        assert text == cli, fmt
    assert f'mass="{r.mass!r}"' in r.to_mjcf() or str(r.mass)[:8] in r.to_mjcf()
    with pytest.raises(ValueError, match="format"):
        r.export("step")


def test_body_file_parts_and_warnings():
    r = il.analyze_file(ASSETS / "hammer.toml")
    d = r.to_dict()
    assert d["kind"] == "composite" and len(d["parts"]) == 2
    assert math.isclose(r.mass, sum(p["mass"] for p in d["parts"]), rel_tol=1e-14)
    assert r.volume is None and r.density is None
    assert json.loads(r.to_json()) == d


def test_an_overlap_budget_of_zero_compares_no_shell(tmp_path):
    path = tmp_path / "two_cubes.obj"
    path.write_text(DEFECTS["two_cubes.obj"])
    full = {w["code"]: w for w in il.analyze_file(path).warnings}["overlapping_shells"]
    assert (full["compared"], full["candidates"]) == (1, 1)
    assert abs(full["overlap_volume"] - 0.5) < 0.05
    quick = {w["code"]: w for w in il.analyze_file(path, repairs=il.Repairs(overlap_budget=0)).warnings}
    cut = quick["overlapping_shells"]
    assert (cut["compared"], cut["candidates"]) == (0, 1)
    assert cut["uncompared_bound"] == 1.0
    with pytest.raises(ValueError, match="overlap_budget"):
        il.analyze_file(path, repairs=il.Repairs(overlap_budget=-1))
