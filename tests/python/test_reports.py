"""diagnose, replay, records, study and inspect return what json.loads makes of the
command's --json report for the same input: key by key, in order, floats exact."""

import json

import pytest

import aloft
from conftest import EXAMPLES, RACQUET, assert_same_report, program_json, run_program, shared_data

# Timings differ from run to run; everything else in results.json is the same.
STUDY_TIMES = ("wall_time_s", "phase_time_s")


def test_replay_equals_the_command(tmp_path):
    body, imu = EXAMPLES / "throw_body.json", EXAMPLES / "throw_imu.csv"
    ours = aloft.replay(str(body), imu=str(imu))
    assert_same_report(ours, program_json(tmp_path, "replay", "--body", body, "--imu", imu))
    assert ours["flights"], "the example throw has a flight"
    # A dict body is the same body.
    assert_same_report(aloft.replay(json.loads(body.read_text()), imu=imu), ours)


def test_records_equals_the_command():
    dump = EXAMPLES / "flight_records.bin"
    theirs = json.loads(run_program("records", dump, "--json").stdout)
    assert_same_report(aloft.records(str(dump)), theirs)


@pytest.mark.parametrize("parts", [
    ("real", "racquet", "2025-01-16_17-10-11", "gyro.csv"),
    ("real", "racquet", "2025-01-16_17-10-11", "segments.csv"),
    ("practice", "case00", "imu.csv"),
    ("c3d", "sample01", "Eb015pi.c3d"),
])
def test_inspect_equals_the_command(parts):
    path = shared_data(*parts)
    assert_same_report(aloft.inspect(str(path)), json.loads(run_program("inspect", path).stdout))


def test_inspect_passes_the_commands_options():
    imu = EXAMPLES / "throw_imu.csv"
    theirs = json.loads(run_program("inspect", imu, "--gyro-units", "deg/s").stdout)
    assert_same_report(aloft.inspect(imu, gyro_units="deg/s"), theirs)


def test_diagnose_one_flight_equals_the_command(tmp_path):
    case = shared_data("practice", "case00")
    ours = aloft.diagnose(str(case / "body.json"), imu=str(case / "imu.csv"))
    theirs = program_json(tmp_path, "diagnose", "--body", case / "body.json", "--imu", case / "imu.csv")
    assert_same_report(ours, theirs)


@pytest.mark.parametrize("session", ["2025-01-16_17-10-11", "2025-01-23_18-29-01"])
def test_diagnose_session_equals_the_command(tmp_path, session):
    folder = shared_data("real", "racquet", session)
    body, imu, segments = RACQUET / "body.json", folder / "gyro.csv", folder / "segments.csv"
    ours = aloft.diagnose(body, imu=imu, segments=segments, threads=2)
    theirs = program_json(tmp_path, "diagnose", "--body", body, "--imu", imu, "--segments", segments,
                          "--threads", 2)
    assert_same_report(ours, theirs)
    assert len(ours["flights"]) >= 2


def test_diagnose_writes_what_the_command_writes(tmp_path):
    case = shared_data("practice", "case00")
    ours = aloft.diagnose(case / "body.json", imu=case / "imu.csv", json=tmp_path / "ours.json")
    assert_same_report(json.loads((tmp_path / "ours.json").read_text()), ours)


def test_study_built_in_equals_the_command(tmp_path):
    ours = aloft.study(mc_samples=40, seed=3, threads=2)
    run_program("study", "--mc-samples", 40, "--seed", 3, "--threads", 2, "--out", tmp_path / "cli")
    theirs = json.loads((tmp_path / "cli" / "results.json").read_text())
    assert_same_report(ours, theirs, skip=STUDY_TIMES)
    assert ours["monte_carlo"][0]["simulations"] == 40


def test_study_recording_equals_the_command_and_writes_its_folder(tmp_path):
    folder = shared_data("real", "racquet", "2025-01-16_17-10-11")
    args = dict(body=RACQUET / "body.json", imu=folder / "gyro.csv", segments=folder / "segments.csv")
    ours = aloft.study(**args, mc_samples=30, threads=2, out=tmp_path / "py")
    run_program("study", "--body", args["body"], "--imu", args["imu"], "--segments", args["segments"],
                "--mc-samples", 30, "--threads", 2, "--out", tmp_path / "cli")
    theirs = json.loads((tmp_path / "cli" / "results.json").read_text())
    assert_same_report(ours, theirs, skip=STUDY_TIMES)
    written = json.loads((tmp_path / "py" / "results.json").read_text())
    assert_same_report(written, ours, skip=STUDY_TIMES)
    assert sorted(p.name for p in (tmp_path / "py").iterdir()) == sorted(
        p.name for p in (tmp_path / "cli").iterdir())


def test_diagnose_markers_equals_the_command(tmp_path):
    case = shared_data("practice", "case10")
    ours = aloft.diagnose(case / "body.json", markers=case / "markers.trc")
    theirs = program_json(tmp_path, "diagnose", "--body", case / "body.json", "--markers", case / "markers.trc")
    assert_same_report(ours, theirs)


def test_diagnose_dict_body_writes_the_commands_corrected_body_and_plots(tmp_path):
    case = shared_data("practice", "case01")  # wrong moments: the verdict fits a tensor
    body = json.loads((case / "body.json").read_text())
    ours = aloft.diagnose(body, imu=case / "imu.csv", corrected_body=tmp_path / "ours_body.json",
                          plot=tmp_path / "ours_plots")
    run_program("diagnose", "--body", case / "body.json", "--imu", case / "imu.csv", "--json",
                tmp_path / "theirs.json", "--corrected-body", tmp_path / "theirs_body.json", "--plot",
                tmp_path / "theirs_plots")
    assert_same_report(ours, json.loads((tmp_path / "theirs.json").read_text()))
    assert (tmp_path / "ours_body.json").read_text() == (tmp_path / "theirs_body.json").read_text()
    ours_plots = sorted(p.name for p in (tmp_path / "ours_plots").iterdir())
    assert ours_plots and ours_plots == sorted(p.name for p in (tmp_path / "theirs_plots").iterdir())
