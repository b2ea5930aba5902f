"""At scale on existing engines: the Dask and Ray examples (``crates/py/examples``) give
``measure_files``' rows, one per file, on a folder of the repository's real meshes, body files
and broken files.

Select them with ``-k dask``, ``-k ray`` or ``-k spark``. Without Dask, Ray, pyspark or a Java
runtime a test prints ``SKIPPED …`` and passes, except under ``CI``, where it fails.
"""

from __future__ import annotations

import importlib
import importlib.util
import math
import os
import shutil
import sys
from pathlib import Path
from typing import Any

import pytest

import inertialab as il
from conftest import ASSETS, REAL, REPO, skip_or_fail

pa = pytest.importorskip("pyarrow")
pq = pytest.importorskip("pyarrow.parquet")

EXAMPLES = REPO / "crates" / "py" / "examples"
# Ray Data's own DataContext warns about its deprecated fields as it copies itself.
# PySpark 4.3 warns that pandas 3 is not fully supported (the example does not use pandas).
pytestmark = [
    pytest.mark.filterwarnings("ignore::DeprecationWarning:ray.data.context"),
    pytest.mark.filterwarnings("ignore:PySpark does not yet fully support pandas:FutureWarning"),
]

# Timings differ from run to run; every other column is the same code's output, bit for bit.
TIMINGS = {"parse_ms", "compute_ms"}
# The files that are no body: garbage, nothing, a TOML that is not a body file.
BROKEN = {"broken.obj", "empty.stl", "notes.toml"}


def needs(test: str, module: str, install: str) -> None:
    """Skips (or under CI fails) ``test`` when ``module`` cannot be imported."""
    try:
        importlib.import_module(module)
    except ImportError as e:
        skip_or_fail(test, f"cannot import {module}: {e}", install)


def example(name: str) -> Any:
    """The example ``crates/py/examples/<name>.py`` as a module."""
    spec = importlib.util.spec_from_file_location(name, EXAMPLES / f"{name}.py")
    module = importlib.util.module_from_spec(spec)
    sys.modules[name] = module
    spec.loader.exec_module(module)
    return module


@pytest.fixture(scope="module")
def meshes(tmp_path_factory) -> Path:
    """A folder of real files: the assets' meshes and body files (side by side, as the body
    files name them), the real STLs in a subfolder, and three files that are no body."""
    folder = tmp_path_factory.mktemp("meshes")
    for f in ASSETS.iterdir():
        if f.suffix.lower() in (".obj", ".stl", ".toml"):
            shutil.copy(f, folder / f.name)
    (folder / "real").mkdir()
    for f in REAL.glob("*.stl"):
        shutil.copy(f, folder / "real" / f.name)
    (folder / "broken.obj").write_text("this is not an OBJ file\n\x00\x01 garbage 12 x y z\n")
    (folder / "empty.stl").write_bytes(b"")
    (folder / "notes.toml").write_text('title = "not a body file"\n[owner]\nname = "someone"\n')
    return folder


def files_of(folder: Path) -> list[Path]:
    """The mesh files of ``folder``, listed here rather than by inertialab."""
    return sorted(p for p in folder.rglob("*") if p.is_file() and p.suffix.lower() in (".obj", ".stl", ".toml"))


def read_rows(out: Path) -> tuple[Any, dict[str, dict[str, Any]]]:
    """The schema and the rows, by path, of every Parquet file in ``out``; a path once only."""
    shards = sorted(out.rglob("*.parquet"))
    assert shards, f"no Parquet file in {out}"
    tables = [pq.read_table(s) for s in shards]
    schema = tables[0].schema
    for t in tables[1:]:
        assert t.schema.equals(schema), f"the shards' schemas differ:\n{t.schema}\n{schema}"
    rows: dict[str, dict[str, Any]] = {}
    for t in tables:
        for row in t.to_pylist():
            assert row["path"] not in rows, f"{row['path']} has two rows"
            rows[row["path"]] = row
    return schema, rows


@pytest.fixture(scope="module")
def reference(meshes, tmp_path_factory) -> dict[str, dict[str, Any]]:
    """``measure_files``' rows of the folder, by path."""
    out = tmp_path_factory.mktemp("measure_files")
    summary = il.measure_files(meshes, out, workers=2, progress=False)
    schema, rows = read_rows(out)
    assert schema.equals(il.batch_schema())
    assert summary.files == len(rows)
    return rows


def same_value(a: Any, b: Any) -> bool:
    if isinstance(a, float) and isinstance(b, float) and math.isnan(a) and math.isnan(b):
        return True
    return type(a) is type(b) and a == b


def check_rows(folder: Path, rows: dict[str, dict[str, Any]]) -> None:
    """One row a file, named by its absolute path; the files that are no body are errors with
    a kind and a message, the others ok or warn with a positive mass."""
    files = files_of(folder)
    assert len(rows) == len(files), f"{len(rows)} rows for {len(files)} files"
    assert set(rows) == {str(f.resolve()) for f in files}
    for path, row in rows.items():
        name = Path(path).name
        if name in BROKEN:
            assert row["status"] == "error", row
            assert row["error_kind"], row
            assert row["error_message"], row
        else:
            assert row["status"] in ("ok", "warn"), row
            assert row["error_kind"] is None and row["mass"] > 0, row
        if row["status"] == "error":
            assert row["error_kind"] is not None, row
        # Every file could be read: its bytes were hashed.
        assert row["id"] is not None and len(row["id"]) == 64, row


def check_same(got: dict[str, dict[str, Any]], want: dict[str, dict[str, Any]]) -> None:
    """The same paths, and for each every column but the timings equal (floats exactly)."""
    assert sorted(got) == sorted(want)
    for path in want:
        g, w = got[path], want[path]
        assert g.keys() == w.keys()
        differ = {k: (g[k], w[k]) for k in w if k not in TIMINGS and not same_value(g[k], w[k])}
        assert not differ, f"{path}: {differ}"


def check_schema(schema: Any) -> None:
    """The batch table's columns and types (an engine may write its own metadata)."""
    want = il.batch_schema()
    assert schema.names == want.names
    assert [f.type for f in schema] == [f.type for f in want], (
        "column types differ: "
        + ", ".join(f"{f.name} {f.type} (not {w.type})" for f, w in zip(schema, want) if f.type != w.type)
    )


def test_measure_files_rows(meshes, reference):
    check_rows(meshes, reference)
    bodies = [r for p, r in reference.items() if p.endswith(".toml") and r["status"] != "error"]
    assert len(bodies) == len(list(ASSETS.glob("*.toml")))
    assert all(r["method"] == "composite" for r in bodies)


def test_dask_matches_measure_files(meshes, reference, tmp_path):
    for module in ("dask.dataframe", "dask.distributed"):
        needs("test_dask_matches_measure_files", module, "pip install 'dask[dataframe,distributed]'")
    dask_batch = example("dask_batch")
    out = tmp_path / "out"
    # Small chunks: several partitions on each of the two workers.
    n = dask_batch.main(meshes, out, workers=2, chunk=4)
    schema, rows = read_rows(out)
    assert n == len(rows)
    check_schema(schema)
    check_rows(meshes, rows)
    check_same(rows, reference)


@pytest.fixture(scope="module")
def ray_session():
    """One Ray for the module's Ray tests (it takes seconds to start), shut down after them."""
    import ray

    ray_batch = example("ray_batch")
    ray_batch.init(2)
    try:
        yield ray_batch
    finally:
        ray.shutdown()


def ray_example(request) -> Any:
    """The Ray example, on the module's Ray; skips (or under CI fails) without Ray."""
    needs(request.node.name, "ray.data", "pip install 'ray[data]'")
    return request.getfixturevalue("ray_session")


def test_ray_matches_measure_files(meshes, reference, request, tmp_path):
    ray_batch = ray_example(request)
    out = tmp_path / "out"
    n = ray_batch.main(meshes, out, workers=2)
    schema, rows = read_rows(out)
    assert n == len(rows)
    check_schema(schema)
    assert schema.metadata[b"inertialab.batch_schema_version"] == str(il.BATCH_SCHEMA_VERSION).encode()
    check_rows(meshes, rows)
    check_same(rows, reference)


def test_ray_relative_paths_and_one_file_a_block(meshes, reference, request, tmp_path, monkeypatch):
    ray_batch = ray_example(request)
    # Ray names a file as it was given: relative paths come out relative unless the example
    # makes them absolute, and a body file given as bytes must still find its meshes.
    monkeypatch.chdir(meshes)
    relative = [str(p.relative_to(meshes)) for p in files_of(meshes)]
    assert not any(os.path.isabs(p) for p in relative)
    out = tmp_path / "out"
    n = ray_batch.main(None, out, workers=2, num_blocks=len(relative), files=relative)
    _, rows = read_rows(out)
    assert n == len(rows) == len(relative)
    check_rows(meshes, rows)
    check_same(rows, reference)


def test_spark_matches_measure_files(meshes, reference, tmp_path):
    name = "test_spark_matches_measure_files"
    try:
        import pyspark  # noqa: F401
    except ImportError:
        skip_or_fail(name, "pyspark is not installed", "pip install pyspark==4.3.0")
    if shutil.which("java") is None and not os.environ.get("JAVA_HOME"):
        skip_or_fail(name, "no Java runtime (Spark 4 needs 17 or later)", "apt-get install openjdk-17-jre-headless")
    spark_batch = example("spark_batch")
    out = tmp_path / "out"
    n = spark_batch.main(meshes, out, workers=2)
    schema, rows = read_rows(out)
    assert n == len(rows)
    check_schema(schema)
    check_rows(meshes, rows)
    check_same(rows, reference)
