"""The batch: one row per input row whatever the file holds, the same numbers as one file at a
time, and a resumed run that writes no id twice."""

import math
import os
import shutil
import signal
import subprocess
import sys
import textwrap

import numpy as np
import pyarrow as pa
import pyarrow.parquet as pq

import pytest

import inertialab as il
from conftest import ASSETS, REAL, props_json


@pytest.fixture()
def folder(tmp_path):
    """Real meshes, a body file with its meshes, and files that give no body."""
    for p in list(ASSETS.glob("*.obj")) + list(ASSETS.glob("*.toml")) + list(REAL.glob("*.stl")):
        shutil.copy(p, tmp_path / p.name)
    (tmp_path / "broken.obj").write_text("v 0 0 0\nv 1 0 0\nf 1 2 x\n")
    (tmp_path / "empty.stl").write_bytes(b"")
    (tmp_path / "notes.toml").write_text("title = 'not a body file'\n")
    (tmp_path / "sheet.obj").write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")
    return tmp_path


def test_schema_is_versioned_and_documented():
    schema = il.batch_schema()
    assert schema.metadata[b"inertialab.batch_schema_version"] == str(il.BATCH_SCHEMA_VERSION).encode()
    names = schema.names
    assert len(names) == len(set(names))
    assert names[:4] == ["id", "path", "size_bytes", "status"]
    readme = (ASSETS.parent / "docs" / "python.md").read_text()
    missing = [n for n in names if f"`{n}`" not in readme and not n.startswith("w_")]
    assert not missing, f"docs/python.md's batch table does not document {missing}"


def test_one_row_per_row_never_raising(folder):
    paths = sorted(str(p) for p in folder.iterdir()) + [str(folder / "missing.obj")]
    table = il.measure_table(pa.table({"path": paths}))
    assert table.num_rows == len(paths)
    rows = {os.path.basename(r["path"]): r for r in table.to_pylist()}
    assert [r["path"] for r in table.to_pylist()] == paths
    expected_errors = {
        "broken.obj": "malformed",
        "empty.stl": "malformed",
        "notes.toml": "malformed",
        "sheet.obj": "zero_volume",
        "missing.obj": "io",
    }
    for name, kind in expected_errors.items():
        r = rows[name]
        assert (r["status"], r["error_kind"]) == ("error", kind), (name, r["error_kind"], r["error_message"])
        assert name in r["error_message"]
        assert r["mass"] is None
    assert rows["missing.obj"]["id"] is None
    good = [n for n in rows if n not in expected_errors]
    assert len(good) >= 10
    for name in good:
        r = rows[name]
        assert r["status"] in ("ok", "warn") and r["error_kind"] is None
        d = props_json("test_one_row_per_row_never_raising", folder / name)
        assert r["mass"] == d["mass"]
        assert [r["com_x"], r["com_y"], r["com_z"]] == d["center_of_mass"]
        tensor = [[r[f"i_{a}{b}"] for b in "xyz"] for a in "xyz"]
        assert tensor == d["inertia_com"]
        assert [r["i1"], r["i2"], r["i3"]] == d["principal_moments"]
        assert (r["status"] == "warn") == bool(d.get("warnings") or any(p["warnings"] for p in d.get("parts", [])))
        if "parts" not in d:
            assert r["volume"] == d["volume"] and r["closed"] == d["mesh"]["closed"]
            assert r["shells"] == len(d["shells"]) and r["triangles"] == d["mesh"]["triangles"]
            for w in d["warnings"]:
                assert r[f"w_{w['code']}"] == w["count"]
        q = np.array([r["q_w"], r["q_x"], r["q_y"], r["q_z"]])
        assert abs(np.linalg.norm(q) - 1) < 1e-12 and q[0] >= 0


def test_bytes_and_densities(folder):
    paths = [str(folder / "t_handle.obj"), str(folder / "hammer.toml"), str(folder / "broken.obj")]
    contents = [open(p, "rb").read() for p in paths]
    table = il.measure_table(
        pa.table({"file": paths, "data": contents, "rho": [2.0, None, 3.0]}),
        path_col="file", bytes_col="data", density_col="rho",
    )
    rows = table.to_pylist()
    one = il.analyze_file(paths[0], density=2.0)
    assert rows[0]["mass"] == one.mass and rows[0]["density"] == 2.0
    assert rows[1]["mass"] == il.analyze_file(paths[1]).mass and rows[1]["method"] == "composite"
    assert rows[2]["status"] == "error"
    import hashlib

    assert rows[0]["id"] == hashlib.sha256(contents[0]).hexdigest()
    with pytest.raises(KeyError, match="no column 'nope'"):
        il.measure_table(pa.table({"path": paths}), bytes_col="nope")
    # A RecordBatch is a batch too.
    batch = pa.record_batch({"path": paths[:1]})
    assert il.measure_table(batch).column("mass").to_pylist() == [il.analyze_file(paths[0]).mass]


def test_bytes_named_by_no_extension_are_known_by_their_signature():
    # A PLY unit tetrahedron whose row names no file type: its `ply` line says what it is.
    ply = (
        "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
        "property float z\nelement face 4\nproperty list uchar int vertex_indices\nend_header\n"
        "0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n"
    ).encode()
    table = il.measure_table(
        pa.table({"path": ["scan-0042", "scan-0043.dat"], "data": [ply, b"hello"]}),
        bytes_col="data",
    )
    rows = table.to_pylist()
    assert rows[0]["status"] == "ok" and math.isclose(rows[0]["mass"], 1 / 6, rel_tol=1e-15)
    assert rows[1]["status"] == "error"


def test_measure_files_writes_every_file_once(folder, tmp_path_factory):
    out = tmp_path_factory.mktemp("out")
    summary = il.measure_files(folder, out, workers=2, progress=False, shard_rows=3)
    files = il.mesh_files(folder)
    table = pq.read_table(out)
    assert table.num_rows == len(files) == summary.files
    assert sorted(table.column("path").to_pylist()) == sorted(files)
    assert summary.error == 4 and summary.ok + summary.warn == len(files) - 4
    again = il.measure_files(folder, out, workers=2, progress=False)
    assert again.skipped == len(files) and again.shards == 0
    assert pq.read_table(out).num_rows == len(files)


KILLED_RUN = textwrap.dedent(
    """
    import os, signal, sys
    import pyarrow.parquet as pq
    import inertialab as il
    write = pq.write_table
    written = []
    def write_then_die(table, where, **kw):
        write(table, where, **kw)
        written.append(where)
        if len(written) == 3:  # the third shard is written but not yet renamed: killed here
            os.kill(os.getpid(), signal.SIGKILL)
    pq.write_table = write_then_die
    il.measure_files(sys.argv[1], sys.argv[2], workers=1, progress=False, shard_rows=2)
    """
)


def test_resume_after_a_killed_run_writes_no_id_twice(folder, tmp_path_factory):
    out = tmp_path_factory.mktemp("out")
    killed = subprocess.run([sys.executable, "-c", KILLED_RUN, str(folder), str(out)])
    assert killed.returncode == -signal.SIGKILL
    whole = sorted(out.glob("part-*.parquet"))
    assert len(whole) == 2, "two shards renamed before the kill"
    assert len(list(out.glob(".part-*.tmp"))) == 1, "the third was left under its temporary name"
    summary = il.measure_files(folder, out, workers=2, progress=False)
    files = il.mesh_files(folder)
    assert summary.skipped == 4
    table = pq.read_table(out)
    ids = [i for i in table.column("id").to_pylist() if i is not None]
    assert len(ids) == len(set(ids)), "an id written twice"
    assert sorted(table.column("path").to_pylist()) == sorted(files)


def test_mesh_files_of_a_folder_a_glob_and_a_list(folder):
    (folder / "sub").mkdir()
    (folder / "sub" / "deep.STL").write_bytes(b"")
    (folder / "readme.txt").write_text("not a mesh")
    found = il.mesh_files(folder)
    assert found == sorted(found) and str(folder / "sub" / "deep.STL") in found
    assert not any(p.endswith(".txt") for p in found)
    assert il.mesh_files(str(folder / "**" / "*.STL")) == [str(folder / "sub" / "deep.STL")]
    assert il.mesh_files([folder / "b.obj", folder / "a.obj"]) == [str(folder / "b.obj"), str(folder / "a.obj")]
