"""Robot descriptions from Python: `inertialab.audit` is `inertia-lab audit --json`'s object for
the same file and options, and `audit_table` its links as Arrow rows."""

import json
import subprocess

import pytest

import inertialab as il
from conftest import REPO, props_binary

PANDA = REPO / "tests" / "data" / "robots" / "franka_panda" / "panda.urdf"


def cli_audit(test, *args):
    out = subprocess.run(
        [props_binary(test), "audit", *map(str, args), "--json"], capture_output=True, check=True
    )
    return json.loads(out.stdout)


def test_audit_is_the_clis_object():
    test = "test_audit_is_the_clis_object"
    assert il.audit(PANDA) == cli_audit(test, PANDA)
    nearest = il.audit(PANDA, nearest=True, max_moment_error=0.5)
    assert nearest == cli_audit(test, PANDA, "--fix-mode", "nearest", "--max-moment-error", "0.5")
    finger = next(l for l in nearest["links"] if l["name"] == "panda_leftfinger")
    assert finger["nearest"]["mass"] == 0.1 and finger["nearest"]["moved"] > 0


def test_measured_masses_as_a_dict_or_a_file(tmp_path):
    test = "test_measured_masses_as_a_dict_or_a_file"
    csv = tmp_path / "masses.csv"
    csv.write_text("panda_link1,3.1,0,-0.035,-0.06\npanda_hand,0.9\n")
    from_dict = il.audit(PANDA, masses={"panda_link1": (3.1, (0, -0.035, -0.06)), "panda_hand": 0.9})
    assert from_dict == il.audit(PANDA, masses=csv) == cli_audit(test, PANDA, "--masses", csv)
    link1 = next(l for l in from_dict["links"] if l["name"] == "panda_link1")
    assert link1["computed"]["mass"] == 3.1 and link1["computed"]["basis"] == "measured_mass"
    with pytest.raises(ValueError, match='no link named "wrist"'):
        il.audit(PANDA, masses={"wrist": 1.0})


def test_audit_table_has_a_row_per_link():
    table = il.audit_table([PANDA], nearest=True)
    report = il.audit(PANDA, nearest=True)
    assert table.num_rows == len(report["links"]) == 13
    rows = {r["link"]: r for r in table.to_pylist()}
    finger = rows["panda_leftfinger"]
    assert finger["impossible"] and finger["flagged"] and "impossible_moment" in finger["findings"]
    assert finger["stated_mass"] == 0.1
    impossible = [l for l in report["links"] if any(f.get("proof") for f in l["findings"])]
    assert sum(r["impossible"] for r in rows.values()) == len(impossible) == 11


def test_errors_are_python_errors(tmp_path):
    with pytest.raises(FileNotFoundError):
        il.audit(tmp_path / "absent.urdf")
    bad = tmp_path / "bad.urdf"
    bad.write_text("<robot name='r'><link name='a'>")
    with pytest.raises(ValueError, match="bad.urdf:1"):
        il.audit(bad)
    with pytest.raises(ValueError, match="geometry"):
        il.audit(PANDA, geometry="both")


SDF_ARM = REPO / "tests" / "data" / "robots" / "sdf_arm"


def test_sdformat_is_read_with_model_uris_from_packages():
    test = "test_sdformat_is_read_with_model_uris_from_packages"
    report = il.audit(SDF_ARM / "arm.sdf", packages={"gripper": SDF_ARM / "models" / "gripper"})
    assert report["format"] == "sdf"
    names = [l["name"] for l in report["links"]]
    assert names == ["base", "upper", "forearm_model::forearm", "hand::finger"]
    finger = report["links"][3]
    assert "impossible_moment" in [f["code"] for f in finger["findings"]]
    assert finger["pose"]["position"] == pytest.approx([0, 0, 0.9], abs=1e-15)
    cli = cli_audit(test, SDF_ARM / "arm.sdf", "--package", f"gripper={SDF_ARM / 'models' / 'gripper'}")
    assert report == cli


def test_a_xacro_file_is_expanded_with_its_arguments():
    gripper = REPO / "tests" / "data" / "robots" / "xacro_gripper" / "gripper.urdf.xacro"
    report = il.audit(gripper, xacro_args={"finger_mass": 0.05})
    masses = {l["name"]: l["stated"]["mass"] for l in report["links"]}
    assert masses == {"palm": 0.3, "left_finger": 0.05, "right_finger": 0.05}
    assert il.audit(gripper)["links"][1]["stated"]["mass"] == 0.02
