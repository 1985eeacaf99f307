"""`mpirun -np N brdftab generate` against the single-process run (CTest label `mpi`).

- identity: the files of N = 1, 2, 3 ranks (1 thread each, and 2 ranks x 2 threads) are the
  single-process files byte for byte;
- resume: all ranks SIGKILLed mid-run, restarted with the same command: the same file, and no
  row in the checkpoint is computed again (rows logged by BRDFTAB_TEST_ROW_LOG against the
  checkpoint's records, read here with hashlib, independently of the C++ reader);
- failing rank: a row that throws (BRDFTAB_TEST_FAIL_ROW) or aborts its process ends the job
  with a nonzero exit naming the rank and the row; no table file, the checkpoint stays;
- damaged / foreign / torn checkpoints: discarded, refused, trimmed, each with a message.

Environment: BRDFTAB_EXE (the brdftab executable, brdftab-mpi beside it), MPIRUN.
"""
import hashlib
import json
import os
import re
import signal
import struct
import subprocess
import tempfile
import time
from pathlib import Path

import pytest

EXE = os.environ.get("BRDFTAB_EXE", "brdftab")
MPIRUN = os.environ.get("MPIRUN", "mpirun")
DATASET = "demo_exp_cos"


def mpirun_args(n):
    args = [MPIRUN, "-np", str(n), "--oversubscribe"]
    if os.geteuid() == 0:
        args.append("--allow-run-as-root")
    return args


def env(**extra):
    e = dict(os.environ)
    for k in ("BRDFTAB_TEST_FAIL_ROW", "BRDFTAB_TEST_ROW_LOG", "BRDFTAB_TEST_ROW_SLEEP_MS"):
        e.pop(k, None)
    # Shared memory between the ranks without ptrace-based single copy (containers).
    e.setdefault("OMPI_MCA_btl_vader_single_copy_mechanism", "none")
    e.update({k: str(v) for k, v in extra.items()})
    return e


def generate(manifest, out, ranks=None, threads=1, extra=(), **env_extra):
    cmd = [EXE, "generate", "--manifest", str(manifest), "--tables", str(out), "--quiet", "--threads", str(threads)]
    cmd += list(extra)
    if ranks is not None:
        cmd = mpirun_args(ranks) + cmd
    return subprocess.run(cmd, capture_output=True, text=True, env=env(**env_extra), timeout=120)


def write_manifest(path, x_points=24, y_step=0.09817477042468103):
    path.write_text(json.dumps({"schema_version": 1, "tables": {
        "demo": {"x_points": x_points, "y_range": [0, 1.5707963267948966], "y_step": y_step,
                 "precision": "float64", "interpolation": "cubic"}}}))
    return path


def read_checkpoint(path):
    """(dataset, stage, index) of every complete record, checking every digest."""
    data = Path(path).read_bytes()
    lines = data.split(b"\n", 4)
    assert lines[0] == b"brdftab-checkpoint 1"
    head = b"\n".join(lines[:3]) + b"\n"
    assert lines[3] == b"digest " + hashlib.sha256(head).hexdigest().encode()
    pos = len(head) + len(lines[3]) + 1
    rows = set()
    while len(data) - pos >= 36:
        (n,) = struct.unpack_from("<I", data, pos)
        if len(data) - pos - 4 < n + 32:
            break
        body = data[pos + 4:pos + 4 + n]
        assert hashlib.sha256(body).digest() == data[pos + 4 + n:pos + 4 + n + 32]
        (ld,) = struct.unpack_from("<H", body, 0)
        dataset = body[2:2 + ld].decode()
        (ls,) = struct.unpack_from("<H", body, 2 + ld)
        stage = body[4 + ld:4 + ld + ls].decode()
        (index,) = struct.unpack_from("<Q", body, 4 + ld + ls)
        rows.add((dataset, stage, index))
        pos += 4 + n + 32
    return rows, pos


def logged(path):
    if not Path(path).exists():
        return []
    out = []
    for line in Path(path).read_text().splitlines():
        d, s, i = line.split()
        out.append((d, s, int(i)))
    return out


def files(d):
    return {p.name: p.read_bytes() for p in sorted(Path(d).glob("*.h5"))}


@pytest.fixture(scope="module")
def work():
    with tempfile.TemporaryDirectory(prefix="brdftab_mpi_") as d:
        yield Path(d)


@pytest.fixture(scope="module")
def reference(work):
    """Single-process run of the small manifest, with the rows it computes logged."""
    m = write_manifest(work / "small.json")
    log = work / "reference.log"
    r = generate(m, work / "ref", threads=2, BRDFTAB_TEST_ROW_LOG=log)
    assert r.returncode == 0, r.stderr
    rows = logged(log)
    assert len(rows) == len(set(rows)) and len(rows) > 100
    assert not list((work / "ref").glob("*.checkpoint")), "the checkpoint is removed once the file is written"
    return m, files(work / "ref"), set(rows)


def test_identity(work, reference):
    manifest, ref, _ = reference
    assert ref
    for ranks, threads in ((1, 1), (2, 1), (3, 1), (2, 2)):
        out = work / f"n{ranks}x{threads}"
        r = generate(manifest, out, ranks=ranks, threads=threads)
        assert r.returncode == 0, r.stdout + r.stderr
        assert f"on {ranks} ranks x {threads} threads" in r.stdout
        got = files(out)
        assert got.keys() == ref.keys()
        for name in ref:
            assert got[name] == ref[name], f"{name} differs at N = {ranks} x {threads}"
        assert not list(out.glob("*.checkpoint"))


def descendants(pid):
    """Every process below pid (children first found through /proc)."""
    parent = {}
    for p in Path("/proc").iterdir():
        if p.name.isdigit():
            try:
                stat = (p / "stat").read_text()
                parent[int(p.name)] = int(stat[stat.rfind(")") + 2:].split()[1])
            except (OSError, ValueError, IndexError):
                pass
    found, todo = [], [pid]
    while todo:
        q = todo.pop()
        kids = [c for c, pp in parent.items() if pp == q]
        found += kids
        todo += kids
    return found


def alive(pid):
    try:
        state = Path(f"/proc/{pid}/stat").read_text()
        return state[state.rfind(")") + 2] != "Z"
    except OSError:
        return False


def test_resume_after_kill(work, reference):
    manifest, ref, all_rows = reference
    out = work / "killed"
    ckpt = out / "demo.h5.checkpoint"
    cmd = mpirun_args(3) + [EXE, "generate", "--manifest", str(manifest), "--tables", str(out), "--quiet", "--threads", "1"]
    p = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                         env=env(BRDFTAB_TEST_ROW_SLEEP_MS=15), start_new_session=True)
    try:
        deadline = time.time() + 60
        while time.time() < deadline:
            if ckpt.exists() and len(read_checkpoint(ckpt)[0]) >= 60:
                break
            time.sleep(0.02)
        else:
            pytest.fail("no checkpoint records appeared")
        ranks = [q for q in descendants(p.pid)]
        assert len(ranks) >= 3
        for q in ranks + [p.pid]:  # SIGKILL every rank and the launcher at once
            try:
                os.kill(q, signal.SIGKILL)
            except ProcessLookupError:
                pass
    finally:
        p.kill()
        p.communicate()
    deadline = time.time() + 20
    while any(alive(q) for q in ranks) and time.time() < deadline:
        time.sleep(0.05)
    assert not any(alive(q) for q in ranks), "a rank survived SIGKILL"
    assert not (out / "demo.h5").exists(), "no table file from a killed job"
    kept, _ = read_checkpoint(ckpt)
    assert 60 <= len(kept) < len(all_rows)
    assert kept <= all_rows

    log = work / "resume.log"
    t = time.time()
    r = generate(manifest, out, ranks=3, BRDFTAB_TEST_ROW_LOG=log)
    resume_seconds = time.time() - t
    assert r.returncode == 0, r.stderr
    assert f"resuming with {len(kept)} finished rows" in r.stderr
    assert f"{len(kept)} from checkpoints" in r.stdout
    again = logged(log)
    assert len(again) == len(set(again))
    assert not (set(again) & kept), "a row in the checkpoint was computed again"
    assert set(again) | kept == all_rows
    assert files(out) == ref
    assert not ckpt.exists()
    print(f"resumed {len(kept)} rows, computed {len(again)} in {resume_seconds:.2f} s")


def test_single_process_resume(work, reference):
    """The single-process generate keeps and reads the same checkpoint."""
    manifest, ref, all_rows = reference
    out = work / "single"
    r = generate(manifest, out, threads=1, BRDFTAB_TEST_FAIL_ROW=f"{DATASET}:measure:40")
    assert r.returncode == 1
    assert f"table '{DATASET}' measure row 40" in r.stderr
    kept, _ = read_checkpoint(out / "demo.h5.checkpoint")
    assert len(kept) >= 40
    log = work / "single.log"
    r = generate(manifest, out, threads=1, BRDFTAB_TEST_ROW_LOG=log)
    assert r.returncode == 0, r.stderr
    again = set(logged(log))
    assert not (again & kept) and again | kept == all_rows
    assert files(out) == ref


@pytest.mark.parametrize("how", ["throw", "abort"])
def test_failing_rank(work, reference, how):
    manifest, _, _ = reference
    out = work / f"fail_{how}"
    spec = f"{DATASET}:fill:7" + (":abort" if how == "abort" else "")
    r = generate(manifest, out, ranks=3, BRDFTAB_TEST_FAIL_ROW=spec)
    assert r.returncode != 0
    if how == "throw":
        assert re.search(rf"rank \d failed on table '{DATASET}' fill row 7 \(x = [0-9.e+-]+\): injected test failure",
                         r.stderr), r.stderr
    else:
        assert re.search(rf"rank \d ended by signal 6 while computing table '{DATASET}' fill row 7", r.stderr), r.stderr
    assert not (out / "demo.h5").exists()
    assert not list(out.glob("*.tmp.*")), "no partial table file"
    assert (out / "demo.h5.checkpoint").exists(), "the checkpoint stays"


def make_checkpoint(work, manifest, name):
    """A checkpoint with some rows (a run that failed in its measure stage)."""
    out = work / name
    r = generate(manifest, out, ranks=2, BRDFTAB_TEST_FAIL_ROW=f"{DATASET}:measure:50")
    assert r.returncode != 0
    ckpt = out / "demo.h5.checkpoint"
    kept, end = read_checkpoint(ckpt)
    assert len(kept) >= 24
    return out, ckpt, end


def test_damaged_checkpoint(work, reference):
    manifest, ref, _ = reference
    out, ckpt, end = make_checkpoint(work, manifest, "damaged")
    data = bytearray(ckpt.read_bytes())
    data[end // 2] ^= 0x01  # one bit inside a record
    ckpt.write_bytes(bytes(data))
    r = generate(manifest, out, ranks=2)
    assert r.returncode == 0, r.stderr
    assert "is damaged" in r.stderr and "discarded" in r.stderr
    assert files(out) == ref


def test_torn_checkpoint(work, reference):
    manifest, ref, _ = reference
    out, ckpt, end = make_checkpoint(work, manifest, "torn")
    kept, _ = read_checkpoint(ckpt)
    ckpt.write_bytes(ckpt.read_bytes()[:end - 5])  # the last record cut short
    log = work / "torn.log"
    r = generate(manifest, out, ranks=2, BRDFTAB_TEST_ROW_LOG=log)
    assert r.returncode == 0, r.stderr
    assert "dropped an unfinished record" in r.stderr
    assert f"resuming with {len(kept) - 1} finished rows" in r.stderr
    assert len(set(logged(log)) & kept) == 1  # only the torn row again
    assert files(out) == ref


def test_foreign_checkpoint(work, reference):
    manifest, ref, _ = reference
    other = write_manifest(work / "other.json", x_points=20)
    src, src_ckpt, _ = make_checkpoint(work, other, "foreign_src")
    out = work / "foreign"
    out.mkdir()
    (out / "demo.h5.checkpoint").write_bytes(src_ckpt.read_bytes())
    r = generate(manifest, out, ranks=2)
    assert r.returncode == 1
    assert "refused" in r.stderr and "content key" in r.stderr
    assert not (out / "demo.h5").exists()
    r = generate(manifest, out, ranks=2, extra=["--discard-checkpoint"])
    assert r.returncode == 0, r.stderr
    assert "discarded" in r.stderr
    assert files(out) == ref


GGX_TABLES = [f"microfacet_albedo_ggx_{q}_compact" for q in ("E_corr", "E_sep", "split_scale", "split_bias")]


def test_affinity(work):
    """The four GGX compact tables share every row's coordinates (and, in the process that
    computed them, the exact E values): at 3 ranks each later table's row goes back to the rank
    that computed the first table's row. The ranks log their rows into separate files (a shell
    wrapper picks the file by the launcher's rank variable). Rank 0 computes from the front of
    each stage and deals from the back, so without affinity ranks 1 and 2 split the back rows in
    the order their requests arrive: the previous dealer scored 65-67% here (the test failed)."""
    manifest = work / "ggx.json"
    manifest.write_text(json.dumps({"schema_version": 1, "tables": {"microfacet_albedo": {
        "ggx": True, "beckmann": False, "gbeckmann": False, "precise": False, "render": False,
        "alpha_range": [0.2, 1], "compact_log_alpha_step": 0.035, "compact_s_step": 0.05, "error_rows": 8,
        "error_per_row": 8, "avg_log_alpha_step": 0.5, "avg_error_points": 4}}}))
    single = work / "ggx_single"
    r = generate(manifest, single, threads=2)
    assert r.returncode == 0, r.stderr
    log = work / "ggx_rank"
    wrapper = 'BRDFTAB_TEST_ROW_LOG="$0.${OMPI_COMM_WORLD_RANK:-${PMI_RANK:-0}}" exec "$@"'
    cmd = mpirun_args(3) + ["sh", "-c", wrapper, str(log), EXE, "generate", "--manifest", str(manifest),
                            "--tables", str(work / "ggx_mpi"), "--quiet", "--threads", "1"]
    r = subprocess.run(cmd, capture_output=True, text=True, env=env(), timeout=120)
    assert r.returncode == 0, r.stdout + r.stderr
    assert files(work / "ggx_mpi") == files(single)
    rank_of = {}
    for rank in (0, 1, 2):
        for row in logged(f"{log}.{rank}"):
            assert row not in rank_of, f"{row} computed twice"
            rank_of[row] = rank
    first = {i: rk for (d, s, i), rk in rank_of.items() if d == GGX_TABLES[0] and s == "fill"}
    assert len(first) >= 40
    shares = [sum(rk == k for rk in first.values()) / len(first) for k in (0, 1, 2)]
    assert min(shares[1:]) >= 0.1, f"ranks 0, 1, 2 computed {shares} of the first table: not a test of affinity"
    # A later table's row is a hit where its rank computed the same row of an earlier table (the
    # exact values are in that rank's cache), counted over the rows dealt to ranks 1 and 2.
    dealt = [i for i, rk in first.items() if rk > 0]
    had = {i: {first[i]} for i in dealt}
    hits = 0
    for d in GGX_TABLES[1:]:
        for i in dealt:
            rk = rank_of[(d, "fill", i)]
            hits += rk in had[i]
            had[i].add(rk)
    hit_rate = hits / (len(dealt) * (len(GGX_TABLES) - 1))
    print(f"ranks 0, 1, 2 computed {[round(x, 2) for x in shares]} of the first table; {hit_rate:.1%} of the later "
          f"tables' rows dealt to ranks 1 and 2 found their values computed on their rank")
    assert hit_rate >= 0.85
    m = re.search(r"(\d+) of (\d+) rows on the rank that had computed their coordinates", r.stdout)
    assert m and int(m.group(2)) >= len(first) * (len(GGX_TABLES) - 1), r.stdout
    assert int(m.group(1)) / int(m.group(2)) >= 0.85, r.stdout


def test_bound_threads_warning(work, reference):
    """--threads 2 on a rank the launcher bound to one core: a warning naming the rank and the
    launcher options (the file is still the same); unbound, no warning."""
    manifest, ref, _ = reference
    for binding, warned in (("core", True), ("none", False)):
        if not warned and len(os.sched_getaffinity(0)) < 2:
            continue
        out = work / f"bound_{binding}"
        cmd = mpirun_args(1) + ["--bind-to", binding, EXE, "generate", "--manifest", str(manifest), "--tables", str(out),
                                "--quiet", "--threads", "2"]
        r = subprocess.run(cmd, capture_output=True, text=True, env=env(), timeout=120)
        assert r.returncode == 0, r.stdout + r.stderr
        assert ("the launcher bound rank 0 (1 CPU)" in r.stderr) == warned, r.stderr
        if warned:
            assert "--map-by slot:PE=2" in r.stderr and "--cpus-per-task=2" in r.stderr
        assert files(out) == ref


def test_scene_needs_tables(work):
    """Under mpirun the same input checks as the single process: --scene without --tables is
    refused (exit 2, one message from rank 0), nothing written."""
    scene = Path(__file__).resolve().parents[2] / "tables" / "scenes" / "metals_and_milk.json"
    cmd = mpirun_args(2) + [EXE, "generate", "--scene", str(scene), "--quiet", "--threads", "1"]
    r = subprocess.run(cmd, capture_output=True, text=True, env=env(), timeout=120, cwd=work)
    assert r.returncode == 2, r.stdout + r.stderr
    assert r.stderr.count("--scene needs --tables DIR") == 1, r.stderr
    assert not (work / "tables").exists()
