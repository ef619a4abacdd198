"""asperity.batch: many surfaces on a Dask cluster into one table. Small synthetic maps (Gaussian
and Weibull marginals) and a broken file, analysed by a LocalCluster of worker processes (the
default path: tasks pickled to other interpreters) and by an in-process cluster reached through
its tcp address on loopback (the scheduler-address path); each row checked against its surface's
own JSON and that JSON against the analysis run here directly; resuming (what is finished is not
submitted again), an interrupted run (killed mid-way; a truncated JSON, a missing marker, a
temporary file left behind), a changed input, the options' fingerprint, the lock. Kept short
(small maps, 49 surrogates). Run by ctest (python_batch)."""
import ast
import csv
import inspect
import fcntl
import json
import math
import os
import re
import shutil
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

import asperity
from asperity import batch, topography

distributed = pytest.importorskip("distributed")  # scripts/setup.sh installs python3-distributed
# two clusters at once (a test's and the tcp one) share no HTTP port: the second takes another;
# Debian's distributed 2022.12 calls a method its tornado deprecates
pytestmark = [pytest.mark.filterwarnings("ignore:Port 8787 is already in use:UserWarning"),
              pytest.mark.filterwarnings("ignore:make_current is deprecated:DeprecationWarning")]

OPTIONS = dict(bootstrap=49, seed=7, contact_modulus=1e11, pressures=[1e6, 1e7])


def write_map(path, n, correlation, seed, weibull=None):
    field = topography.gaussian_random_field(n, n, 1e-6, 1e-6, [topography.SpectrumComponent(correlation, 1.0)],
                                             seed=seed)
    if weibull:
        topography.to_weibull_marginal(field, weibull[0], bounded=weibull[1])
    topography.write_gsf(topography.HeightMap(field.heights * 1e-7, 1e-6, 1e-6), path)


@pytest.fixture(scope="module")
def inputs(tmp_path_factory):
    folder = tmp_path_factory.mktemp("maps")
    (folder / "line-b").mkdir()
    paths = [folder / "part 1.gsf", folder / "part-2.gsf", folder / "worn.gsf", folder / "line-b" / "part 1.gsf"]
    write_map(paths[0], 80, 1.5, 1)
    write_map(paths[1], 80, 2.0, 2, weibull=(1.5, False))
    write_map(paths[2], 80, 1.5, 3, weibull=(2.0, True))
    write_map(paths[3], 64, 1.5, 4)
    broken = folder / "broken.x3p"
    broken.write_bytes(b"PK\x03\x04 not a zip archive")
    return [str(p) for p in paths[:2]] + [str(broken)] + [str(p) for p in paths[2:]]


@pytest.fixture(scope="module")
def tcp_cluster():
    """A cluster in this process (worker threads: the analysis releases the GIL) reached through its
    tcp address on loopback, as a real scheduler is."""
    cluster = distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=False, protocol="tcp",
                                       host="127.0.0.1", dashboard_address=None)
    yield cluster
    cluster.close()


class CountingClient:
    """A distributed.Client that records which files are submitted (what a run analyses)."""

    def __init__(self, address):
        self.client = distributed.Client(address)
        self.submitted = []

    def submit(self, function, path, *args, **kwargs):
        self.submitted.append(path)
        return self.client.submit(function, path, *args, **kwargs)

    def close(self):
        self.client.close()


def lost_on_its_worker(path, *args):
    raise RuntimeError(f"worker lost while analysing {path}")


class FailingClient(CountingClient):
    """The task of files named part-2* fails on its worker (as a worker killed under it does)."""

    def submit(self, function, path, *args, **kwargs):
        if os.path.basename(path).startswith("part-2"):
            function = lost_on_its_worker
        return super().submit(function, path, *args, **kwargs)


@pytest.fixture
def counting(tcp_cluster):
    client = CountingClient(tcp_cluster.scheduler_address)
    yield client
    client.close()


@pytest.fixture(scope="module")
def first_run(inputs, tmp_path_factory):
    """The default path: a LocalCluster of 2 worker processes started by analyse_files."""
    out = tmp_path_factory.mktemp("results")
    rows = batch.analyse_files(inputs, out, n_workers=2, progress=False, **OPTIONS)
    return out, rows


def snapshot(folder):
    return {p.name: (p.stat().st_mtime_ns, p.read_bytes()) for p in Path(folder).iterdir() if p.name != ".batch.lock"}


def copy_results(first_run, tmp_path):
    out = tmp_path / "results"
    shutil.copytree(first_run[0], out)
    return out


# ---- the table and the JSON documents ----

def test_a_row_per_file_in_order_and_an_error_row(inputs, first_run):
    out, rows = first_run
    assert [r["source"] for r in rows] == [os.path.abspath(p) for p in inputs]
    assert [r["status"] for r in rows] == ["analysed", "analysed", "failed", "analysed", "analysed"]
    names = [r["name"] for r in rows]
    assert len(set(names)) == 5 and names[0].startswith("part_1-") and names[4].startswith("part_1-")
    bad = rows[2]
    assert "broken.x3p" in bad["error"] and bad["nx"] is None and bad["Sq_m"] is None
    assert not (out / (bad["name"] + ".json")).exists() and not (out / (bad["name"] + ".done")).exists()
    for row in rows:
        if row["status"] == "analysed":
            assert (out / (row["name"] + ".json")).is_file() and (out / (row["name"] + ".done")).is_file()
            assert row["seconds"] > 0 and row["error"] is None
    assert not [p for p in out.iterdir() if ".tmp-" in p.name]


def test_each_row_holds_its_surfaces_json(first_run):
    out, rows = first_run
    for row in rows:
        if row["status"] != "analysed":
            continue
        d = json.loads((out / (row["name"] + ".json")).read_text())
        assert d["schema"] == "asperity-surface/3" and d["surface"]["source"] == row["source"]
        assert (row["nx"], row["ny"], row["dx_m"]) == (d["surface"]["nx"], d["surface"]["ny"], d["surface"]["dx_m"])
        for column, key in (("Sq_m", "Sq_m"), ("Ssk", "Ssk"), ("Sku", "Sku")):
            assert row[column] == d["statistics"][key]
        assert row["alpha"] == d["spectral_moments"]["alpha"]
        assert row["anisotropy"] == d["spectral_moments"]["anisotropy"]
        assert row["summits"] == d["summits"]["count"] > 30
        assert row["summit_radius_m"] == d["summits"]["radius_m"] and row["surrogates"] == 49
        v = d["verdict"]
        for key in ("gaussian_rejected", "gaussian_p_heights", "gaussian_p_heights_is_bound",
                    "gaussian_p_summit_heights", "gaussian_p_summit_heights_is_bound", "summit_test_applicable",
                    "heights_orientation", "side_told", "side_note", "model_for_contact"):
            assert row[key] == v[key], key
        assert row["verdict_text"] == v["text"]
        for sample in ("summit_heights", "heights"):
            for m in d["fits"][sample]["models"]:
                column = sample + "_" + {"gaussian": "gaussian", "weibull-tail": "weibull_tail",
                                         "weibull-bounded": "weibull_bounded"}[m["model"]]
                assert row[column + "_ad_p"] == m["anderson_darling_p"]
                assert row[column + "_ad_p_is_bound"] == m["anderson_darling_p_is_bound"]
                if m["model"] != "gaussian":
                    assert row[column + "_shape"] == m["shape"] and math.isfinite(m["shape"])
                    assert [row[column + "_shape_lo"], row[column + "_shape_hi"]] == m["interval_shape"]
                    assert row[column + "_shape_identified"] == m["shape_identified"]
        c = d["contact"]
        assert c["pressures_Pa"] == [1e6, 1e7] and row["contact_closest_model"] == (c["closest_fitted_model"] or None)
        for k in range(2):
            assert row[f"pressure_{k}_Pa"] == c["pressures_Pa"][k]
            assert row[f"measured_summits_in_contact_{k}"] == c["measured_summits_in_contact"][k]
            for m in c["models"]:
                column = f"stiffness_over_measured_{k}_{m['model']}"
                if m["model"] == "measured-summits":
                    assert column not in row
                elif m["served"]:
                    assert row[column] == m["at_pressures"][k]["stiffness_over_measured_summits"]
                else:
                    assert row[column] is None
        assert isinstance(row["stiffness_over_measured_0_gaussian"], float)


def test_the_json_is_the_analysis_run_here(first_run):
    # the options reached the worker processes whole: the same document as the analysis here
    out, rows = first_run
    options = topography.AnalysisOptions(assessment=topography.AssessmentOptions(bootstrap=49, seed=7),
                                         contact=topography.ContactOptions(1e11, pressures=[1e6, 1e7]))
    direct = topography.analyse_surface_file(rows[1]["source"], options).json()
    assert (out / (rows[1]["name"] + ".json")).read_text() == direct


def test_the_csv_is_the_table(first_run):
    out, rows = first_run
    with open(out / "surfaces.csv", newline="") as f:
        header = next(csv.reader(f))
    assert header[:len(batch.COLUMNS)] == batch.COLUMNS
    assert header[len(batch.COLUMNS):len(batch.COLUMNS) + 4] == [
        "pressure_0_Pa", "measured_summits_stiffness_spread_0", "measured_summits_in_contact_0",
        "stiffness_over_measured_0_gaussian-moments"]
    table = batch.read_table(out / "surfaces.csv")
    assert len(table) == len(rows)
    for read, row in zip(table, rows):
        assert set(read) == set(header)
        for key in header:
            value = row.get(key)
            assert read[key] == value, key  # floats exactly (repr), None as an empty cell


# ---- resuming ----

def test_a_second_run_analyses_nothing_finished(inputs, first_run, tmp_path, counting):
    out = copy_results(first_run, tmp_path)
    before = snapshot(out)
    rows = batch.analyse_files(inputs, out, scheduler=counting, progress=False, **OPTIONS)
    assert counting.submitted == [os.path.abspath(inputs[2])]  # only the file that failed is tried again
    assert [r["status"] for r in rows] == ["resumed", "resumed", "failed", "resumed", "resumed"]
    after = snapshot(out)
    for name, (mtime, data) in before.items():
        if name != "surfaces.csv":
            assert after[name] == (mtime, data), name
    for resumed, first in zip(rows, first_run[1]):
        assert ({k: v for k, v in resumed.items() if k not in ("status", "seconds")} ==
                {k: v for k, v in first.items() if k not in ("status", "seconds")})
        assert resumed["seconds"] == first["seconds"] or resumed["status"] == "failed"


def test_nothing_to_do_starts_no_cluster(inputs, first_run, tmp_path):
    out = copy_results(first_run, tmp_path)

    class NoCluster:
        def submit(self, *args, **kwargs):
            raise AssertionError("a finished surface was submitted")

    good = [p for p in inputs if not p.endswith("broken.x3p")]
    rows = batch.analyse_files(good, out, scheduler=NoCluster(), progress=False, **OPTIONS)
    assert {r["status"] for r in rows} == {"resumed"}


def test_an_interrupted_run_is_redone_where_unfinished(inputs, first_run, tmp_path, tcp_cluster, capsys):
    out = copy_results(first_run, tmp_path)
    rows = first_run[1]
    first_json = {r["name"]: (out / (r["name"] + ".json")).read_bytes() for r in rows if r["status"] == "analysed"}
    a, b, c, d = [r["name"] for r in rows if r["status"] == "analysed"]
    (out / (a + ".json")).write_bytes(first_json[a][: len(first_json[a]) // 2])  # a JSON cut short
    (out / (b + ".done")).unlink()  # stopped between the JSON's rename and its marker's
    stale = out / f".{c}.json.tmp-0123456789abcdef"  # a temporary file of a killed run
    stale.write_bytes(first_json[c][:100])
    (out / (d + ".done")).write_text('{"fingerprint": ')  # a marker cut short
    # a scheduler's address (tcp on loopback): analyse_files connects a client of its own
    result = batch.analyse_files(inputs, out, scheduler=tcp_cluster.scheduler_address, progress=True, **OPTIONS)
    assert [r["status"] for r in result] == ["analysed", "analysed", "failed", "resumed", "analysed"]
    assert not stale.exists() and not [p for p in out.iterdir() if ".tmp-" in p.name]
    for name, data in first_json.items():
        assert (out / (name + ".json")).read_bytes() == data  # the same documents (reproducible)
    err = capsys.readouterr().err
    assert "asperity batch: 5/5 surfaces (1 failed, 1 resumed)" in err


def test_a_run_killed_midway_resumes(inputs, first_run, tmp_path):
    # a batch in another process, killed (SIGKILL: no clean-up) once a surface is finished
    out = tmp_path / "results"
    script = (f"from asperity import batch; batch.analyse_files({inputs!r}, {str(out)!r}, "
              f"n_workers=1, processes=False, progress=False, **{OPTIONS!r})")
    process = subprocess.Popen([sys.executable, "-W", "ignore:Port 8787 is already in use:UserWarning", "-c", script],
                               env=os.environ.copy(), start_new_session=True)
    try:
        deadline = time.monotonic() + 120
        while time.monotonic() < deadline and process.poll() is None:
            if out.is_dir() and any(p.suffix == ".done" for p in out.iterdir()):
                break
            time.sleep(0.02)
    finally:
        if process.poll() is None:
            os.killpg(process.pid, signal.SIGKILL)
        process.wait()
    finished = {p.stem for p in out.iterdir() if p.suffix == ".done"}
    assert finished, "the batch finished no surface before it was killed"
    rows = batch.analyse_files(inputs, out, n_workers=2, processes=False, progress=False, **OPTIONS)
    for row in rows:
        if row["status"] == "failed":
            continue
        assert row["status"] == ("resumed" if row["name"] in finished else "analysed")
        assert (out / (row["name"] + ".json")).read_bytes() == (first_run[0] / (row["name"] + ".json")).read_bytes()
    assert [r["status"] == "failed" for r in rows] == [False, False, True, False, False]
    assert not [p for p in out.iterdir() if ".tmp-" in p.name]


def test_a_changed_file_or_other_options_are_analysed_again(inputs, first_run, tmp_path, counting):
    out = copy_results(first_run, tmp_path)
    small = inputs[4]  # 64 x 64
    copied = tmp_path / "part-5.gsf"
    shutil.copy(small, copied)
    # a file not seen before (another path): analysed; then its modification time changes (a new
    # measurement under the same name): analysed again
    rows = batch.analyse_files([small, copied], out, scheduler=counting, progress=False, **OPTIONS)
    assert [r["status"] for r in rows] == ["resumed", "analysed"]
    stat = copied.stat()
    os.utime(copied, ns=(stat.st_atime_ns, stat.st_mtime_ns + 10**9))
    rows = batch.analyse_files([small, copied], out, scheduler=counting, progress=False, **OPTIONS)
    assert [r["status"] for r in rows] == ["resumed", "analysed"]
    assert counting.submitted == [str(copied), str(copied)]
    # other options (no ensemble: quick): another fingerprint; resume=False: everything again
    other = dict(OPTIONS, bootstrap=0)
    rows = batch.analyse_files([small], out, scheduler=counting, progress=False, **other)
    assert rows[0]["status"] == "analysed" and rows[0]["surrogates"] == 0
    rows = batch.analyse_files([small], out, scheduler=counting, progress=False, **other)
    assert rows[0]["status"] == "resumed"
    rows = batch.analyse_files([small], out, scheduler=counting, progress=False, resume=False, **other)
    assert rows[0]["status"] == "analysed" and len(counting.submitted) == 4


def test_a_task_lost_on_its_worker_is_an_error_row(inputs, first_run, tmp_path, tcp_cluster):
    out = copy_results(first_run, tmp_path)
    (out / (first_run[1][1]["name"] + ".done")).unlink()  # part-2 to be analysed again
    failing = FailingClient(tcp_cluster.scheduler_address)
    try:
        rows = batch.analyse_files(inputs, out, scheduler=failing, progress=False, **OPTIONS)
    finally:
        failing.close()
    assert failing.submitted == [rows[1]["source"], rows[2]["source"]]
    assert [r["status"] for r in rows] == ["resumed", "failed", "failed", "resumed", "resumed"]
    assert rows[1]["error"] == f"RuntimeError: worker lost while analysing {rows[1]['source']}"
    # its earlier analysis is gone with it: the table and the folder agree
    assert not (out / (rows[1]["name"] + ".json")).exists() and not (out / (rows[1]["name"] + ".done")).exists()


def test_results_of_another_asperity_version_are_not_mixed_in(tmp_path):
    result = {"json": "{}", "error": None, "seconds": 1.0, "source_stat": None, "version": "0.0.1"}
    row = batch._store(str(tmp_path), "x-0123456789", "/x.x3p", "f" * 64, result)
    assert row["status"] == "failed" and "asperity 0.0.1" in row["error"] and list(tmp_path.iterdir()) == []


# ---- options, names, the lock ----

def test_options_fingerprint():
    default = batch.options_fingerprint()
    assert default == batch.options_fingerprint(topography.AnalysisOptions())
    assert len(default) == 64 and int(default, 16) >= 0
    threads = topography.AnalysisOptions(assessment=topography.AssessmentOptions(threads=3))
    assert batch.options_fingerprint(threads) == default  # thread counts do not change results
    for changed in (topography.AnalysisOptions(assessment=topography.AssessmentOptions(seed=2)),
                    topography.AnalysisOptions(level=False), topography.AnalysisOptions(sampling_factors=[1, 2]),
                    topography.AnalysisOptions(read=topography.ReadOptions(format="gsf")),
                    topography.AnalysisOptions(contact=topography.ContactOptions(1e11))):
        assert batch.options_fingerprint(changed) != default


def test_options_cross_to_the_workers_whole():
    options = topography.AnalysisOptions(
        read=topography.ReadOptions(format="x3p", pixel_size_x=2e-6, height_unit="nm"), level=False,
        summits=topography.SummitOptions(window=3, min_drop=1e-9),
        assessment=topography.AssessmentOptions(bootstrap=99, seed=5, confidence=0.9,
                                                fit=topography.FitOptions(0.1, 50.0)),
        sampling_factors=[1, 3], contact=topography.ContactOptions(2e11, 1e-6, [1e5], 31), max_fit_sample=500)
    plain = batch._plain_options(options, analysis_threads=None)
    assert json.loads(json.dumps(plain)) == plain
    again = batch._options_from_plain(plain)
    assert batch._options_to_plain(again) == plain
    assert again.read.format == topography.HeightMapFormat.x3p and again.summits.window == 3
    assert again.contact.pressures == [1e5] and again.assessment.fit.shape_max == 50.0
    # keywords override the options' fields
    plain = batch._plain_options(options, bootstrap=39, contact_modulus=1e9, pressures=[1.0, 2.0])
    made = batch._options_from_plain(plain)
    assert (made.assessment.bootstrap, made.assessment.seed, made.assessment.threads) == (39, 5, 1)
    assert (made.contact.contact_modulus, made.contact.pressures, made.contact.curve_points) == (1e9, [1.0, 2.0], 31)
    # numpy numbers fingerprint as the Python numbers they are
    import numpy as np
    assert (batch._plain_options(None, seed=np.int64(7), contact_modulus=np.float64(1e11), pressures=np.array([1e6]))
            == batch._plain_options(None, seed=7, contact_modulus=1e11, pressures=[1e6]))


def test_exact_contact_options_reach_the_workers(tmp_path, tcp_cluster):
    """Many maps and pressures with the exact contact through the batch (issue 42): its options
    (boundary, kernel, load steps, tolerance) cross to the workers, enter the fingerprint, and the
    solve each JSON describes is the one asked."""
    maps = [tmp_path / f"m{k}.gsf" for k in range(3)]
    for k, path in enumerate(maps):
        write_map(path, 48, 1.5, 10 + k)
    contact = topography.ContactOptions(1e11, pressures=[1e6, 3e6, 1e7], exact=True, exact_boundary="periodic",
                                        exact_kernel="fourier", exact_points=3, exact_tolerance=1e-9)
    options = topography.AnalysisOptions(contact=contact, assessment=topography.AssessmentOptions(bootstrap=0))
    padded = topography.AnalysisOptions(contact=topography.ContactOptions(1e11, pressures=[1e6, 3e6, 1e7], exact=True),
                                        assessment=topography.AssessmentOptions(bootstrap=0))
    assert batch.options_fingerprint(options) != batch.options_fingerprint(padded)
    plain = batch._plain_options(options)
    made = batch._options_from_plain(plain).contact
    assert (made.exact, made.exact_boundary, made.exact_kernel, made.exact_points, made.exact_tolerance) == (
        True, "periodic", "fourier", 3, 1e-9)
    rows = batch.analyse_files([str(p) for p in maps], tmp_path / "out", options, scheduler=tcp_cluster.scheduler_address,
                               progress=False)
    assert [row["status"] for row in rows] == ["analysed"] * 3, [row["error"] for row in rows]
    for row in rows:
        for k in range(3):
            ratio = row[f"stiffness_over_exact_{k}_gaussian"]
            assert ratio is not None and math.isfinite(ratio) and ratio > 0
        text = (tmp_path / "out" / f"{row['name']}.json").read_text()
        assert "48 x 48 points, periodic boundary, fourier kernel, tolerance 1e-09" in text
        assert re.search(r"periodic boundary, fourier kernel, tolerance 1e-09; \d+ load steps", text)


def test_bad_calls_fail_before_any_analysis(tmp_path):
    with pytest.raises(ValueError, match="contact_modulus"):
        batch.analyse_files(["a.x3p"], tmp_path, pressures=[1e6])
    with pytest.raises(TypeError):
        batch.analyse_files(["a.x3p"], tmp_path, options="fast")
    with pytest.raises(TypeError, match="list of paths"):
        batch.analyse_files("a.x3p", tmp_path)
    with pytest.raises(TypeError):
        batch.analyse_files(["a.x3p"], tmp_path, bootstrap="many")
    assert list(tmp_path.iterdir()) == []


def test_output_names():
    a, b = batch.output_name("/data/line-a/part 1.x3p"), batch.output_name("/data/line-b/part 1.x3p")
    assert a != b and a.startswith("part_1-") and b.startswith("part_1-") and len(a) == len("part_1-") + 10
    assert batch.output_name("/data/line-a/../line-a/part 1.x3p") == a
    assert batch.output_name(b"/data/line-a/part 1.x3p") == a
    weird = batch.output_name(b"/data/..\xff\n;rm -rf *.x3p")
    assert re.fullmatch(r"[A-Za-z0-9_][A-Za-z0-9._-]*", weird) and "rm_-rf" in weird
    assert batch.output_name("/data/...").startswith("surface-")
    relative = batch.output_name("part.gsf")
    assert relative == batch.output_name(os.path.join(os.getcwd(), "part.gsf"))


def test_one_run_per_folder(tmp_path):
    with open(tmp_path / ".batch.lock", "a+b") as held:
        fcntl.flock(held.fileno(), fcntl.LOCK_EX | fcntl.LOCK_NB)
        with pytest.raises(RuntimeError, match="another run"):
            batch.analyse_files([], tmp_path, progress=False)
    assert batch.analyse_files([], tmp_path, progress=False) == []
    assert (tmp_path / "surfaces.csv").read_text().startswith("source,name,status,error,")


def test_a_planted_link_at_the_lock_creates_nothing_outside(tmp_path):
    out, outside = tmp_path / "results", tmp_path / "elsewhere"
    out.mkdir()
    outside.mkdir()
    (out / ".batch.lock").symlink_to(outside / "planted")
    with pytest.raises(asperity.Error, match=r"\.batch\.lock.*symbolic link"):
        batch.analyse_files([], out, progress=False)
    assert list(outside.iterdir()) == [] and sorted(p.name for p in out.iterdir()) == [".batch.lock"]


def test_the_results_are_written_through_the_output_policy(tmp_path):
    out, outside = tmp_path / "results", tmp_path / "elsewhere"
    out.mkdir()
    outside.mkdir()
    (outside / "kept.csv").write_text("someone's table\n")
    (out / "surfaces.csv").symlink_to(outside / "kept.csv")  # a planted link: never written through
    with pytest.raises(asperity.Error, match="surfaces.csv"):
        batch.analyse_files([], out, progress=False)
    assert (outside / "kept.csv").read_text() == "someone's table\n"
    (out / "surfaces.csv").unlink()
    (out / "surfaces.csv").write_text("not a table of ours\n")  # a file of another kind: not replaced
    with pytest.raises(asperity.Error, match="surfaces.csv"):
        batch.analyse_files([], out, progress=False)
    assert (out / "surfaces.csv").read_text() == "not a table of ours\n"
    source = Path(batch.__file__).read_text()
    assert not re.search(r"open\([^)]*[\"'][wax]b?\+?[\"']", source), "a file opened for writing by batch.py itself"


NO_GUARD_SCRIPT = """
from asperity import batch
batch.analyse_files([{path!r}], {out!r}, bootstrap=49, n_workers=1, progress=False)
"""


def test_a_script_without_the_main_guard_fails_at_once(tmp_path):
    # the batch at a script's top level: Dask's spawned workers import the script again, and each
    # would start the batch again (restarted forever, no row, no error): refused before any cluster
    script = tmp_path / "no_guard.py"
    body = NO_GUARD_SCRIPT.format(path=str(tmp_path / "missing.gsf"), out=str(tmp_path / "out"))
    script.write_text(body)
    started = time.monotonic()
    done = subprocess.run([sys.executable, str(script)], capture_output=True, text=True, timeout=60,
                          env=os.environ.copy())
    assert done.returncode != 0 and time.monotonic() - started < 30
    assert 'if __name__ == "__main__":' in done.stderr and "no_guard.py (line 3)" in done.stderr
    assert not (tmp_path / "out").exists()
    # under the guard (here in a function called there) the same call runs: a row for the missing file
    script.write_text("def main():" + body.replace("\n", "\n    ") + "\nif __name__ == '__main__':\n    main()\n")
    done = subprocess.run([sys.executable, "-W", "ignore", str(script)], capture_output=True, text=True, timeout=120,
                          env=os.environ.copy())
    assert done.returncode == 0, done.stderr
    assert [row["status"] for row in batch.read_table(tmp_path / "out" / "surfaces.csv")] == ["failed"]


def test_a_worker_importing_the_main_script_fails_at_once(tmp_path):
    # what a spawned worker sees when it imports a script that runs the batch: its __main__ is
    # __mp_main__ (whatever the parent could not see in the script's source)
    code = ("import sys; sys.modules['__main__'].__name__ = '__mp_main__'\n"
            "from asperity import batch\n"
            f"batch.analyse_files([], {str(tmp_path / 'out')!r}, progress=False)\n")
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=60,
                          env=os.environ.copy())
    assert done.returncode != 0 and "while a worker process imported the main script" in done.stderr
    assert 'if __name__ == "__main__":' in done.stderr and not (tmp_path / "out").exists()


def test_row_from_json_refuses_another_schema():
    with pytest.raises(ValueError, match="asperity-surface/3"):
        batch.row_from_json('{"schema": "asperity-surface/1"}')


# ---- documentation ----

def test_docstrings_and_stubs():
    public = {name for name in dir(batch) if not name.startswith("_")} & set(batch.__all__)
    assert set(batch.__all__) == public
    for name in public:
        item = getattr(batch, name)
        if callable(item):
            assert item.__doc__ and len(item.__doc__) > 80, name
    stub = ast.parse((Path(asperity.__file__).parent / "batch.pyi").read_text())
    defined = {node.name for node in stub.body if isinstance(node, ast.FunctionDef)}
    defined |= {node.target.id for node in stub.body if isinstance(node, ast.AnnAssign)}
    assert defined == set(batch.__all__)
    signature = next(n for n in stub.body if isinstance(n, ast.FunctionDef) and n.name == "analyse_files")
    parameters = inspect.signature(batch.analyse_files).parameters
    assert [a.arg for a in signature.args.args + signature.args.kwonlyargs] == list(parameters)
