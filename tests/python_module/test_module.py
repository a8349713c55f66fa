"""The Python module mpmcut (docs/python.md): cases from files, TOML text and dict overrides; runs to the end
and step by step; particle fields as zero-copy views; forces, history and summary; checkpoint and resume; and
the same numbers as the command line, bit for bit."""
import subprocess

import numpy as np
import pytest

import mpmcut

from conftest import SOURCE_DIR

ELASTIC = (SOURCE_DIR / "tests" / "support" / "cases" / "elastic_block.toml").read_text()


def test_overrides_from_a_dict_are_set_strings():
    assert mpmcut.overrides_from({"solver.cfl": 0.3, "body[0].velocity": [1, 0.5], "solver.scheme": "usl",
                                  "solver.remove_escaping_particles": True}) == [
        "solver.cfl=0.3", "body[0].velocity=[1, 0.5]", 'solver.scheme="usl"',
        "solver.remove_escaping_particles=true"]
    assert mpmcut.overrides_from(["solver.cfl=0.2"]) == ["solver.cfl=0.2"]
    with pytest.raises(TypeError, match="not one string"):  # it was taken apart into characters
        mpmcut.overrides_from("solver.cfl=0.2")
    # A value that cannot be written names its key (as every other override error does).
    with pytest.raises(ValueError, match=r"key 'cutting.cutting_speed': 1180591620717411303424 is outside the 64-bit"):
        mpmcut.overrides_from({"cutting.cutting_speed": 2**70})
    with pytest.raises(TypeError, match=r"key 'solver.cfl': cannot write"):
        mpmcut.overrides_from({"solver.cfl": object()})


def test_cases_from_text_file_and_overrides(quick_case):
    case = mpmcut.case_from_toml(ELASTIC, {"solver.end_time": 0.02})
    assert case.title == "block" and case.end_time_s == 0.02 and not case.is_cutting
    cut = mpmcut.load_case(quick_case, {"cutting.cut_length": 0.1e-3})
    assert cut.is_cutting and "[cutting_process]" in cut.toml()
    assert "cut_length = 0.0001" in cut.toml()
    with pytest.raises(mpmcut.InputError, match="no_such_key"):
        mpmcut.case_from_toml(ELASTIC, {"solver.no_such_key": 1})
    with pytest.raises(ValueError):  # InputError is a ValueError
        mpmcut.load_case(quick_case, {"cutting.cutting_speed": -1.0})


def test_python_run_is_bit_identical_to_the_cli(tmp_path, binary, quick_case, short):
    cli = tmp_path / "cli"
    sets = [a for o in mpmcut.overrides_from(short) for a in ("--set", o)]
    subprocess.run([binary, "run", str(quick_case), "--out", str(cli), "--threads", "1", "--fixed-threads",
                    "--no-progress", "--no-plots", *sets], check=True, capture_output=True)
    run = mpmcut.run_case(mpmcut.load_case(quick_case, short), tmp_path / "py", threads=1)
    assert run.status == "complete" and run.exit_code == 0
    for name in ("forces.csv", "history.csv", "rigid_forces.csv", "scene.toml"):
        assert (tmp_path / "py" / name).read_bytes() == (cli / name).read_bytes(), name
    # The arrays are the file's numbers exactly.
    forces = run.forces()
    cli_fc = [float(line.split(",")[1]) for line in (cli / "forces.csv").read_text().splitlines()[1:]]
    assert list(forces.keys())[1] == "cutting_force_N_per_mm"
    assert np.array_equal(forces["cutting_force_N_per_mm"], np.array(cli_fc)) and len(cli_fc) > 100
    history = run.history()
    assert history["step"][-1] == 150
    summary = run.summary()
    assert summary["status"] == "complete" and summary["steps"] == 150 and "energy_J_per_m" in summary


def test_step_by_step_with_a_callback_matches_run_to_end(tmp_path, quick_case, short):
    case = mpmcut.load_case(quick_case, short)
    whole = mpmcut.run_case(case, tmp_path / "whole", threads=1)
    seen = []

    def record(run):
        p = run.particles
        seen.append((run.step_count, float(p["temperature"].max())))

    stepped = mpmcut.run_case(case, tmp_path / "stepped", threads=1, callback=record, every=10)
    assert [s for s, _ in seen] == list(range(10, 150, 10))
    history = stepped.history()
    for step, t_max in seen:  # the views show the state the history row recorded at that step
        assert t_max == history["max_temperature_K"][list(history["step"]).index(step)]
    by_steps = mpmcut.Run(case, tmp_path / "by_steps", threads=1)
    while by_steps.step(7):
        pass
    assert by_steps.finish() == "complete"
    for run in (stepped, by_steps):
        assert (run.out / "forces.csv").read_bytes() == (whole.out / "forces.csv").read_bytes()


def test_particle_fields_are_read_only_views_without_copies(tmp_path):
    run = mpmcut.Run(mpmcut.case_from_toml(ELASTIC), tmp_path / "r", threads=1)
    p = run.particles
    assert set(p) == set(mpmcut.particle_fields)
    n = run.particle_count
    assert p["position"].shape == (n, 2) and p["stress"].shape == (n, 4)
    assert p["deformation_gradient"].shape == (n, 2, 2) and p["body"].dtype == np.int32
    assert np.allclose(p["deformation_gradient"][:, 0, 0], 1.0) and np.allclose(p["velocity"][:, 0], 1.0)
    again = run.particles
    for name in mpmcut.particle_fields:
        assert not p[name].flags.owndata and not p[name].flags.writeable
        assert np.shares_memory(p[name], again[name]), name  # both view the same storage
    with pytest.raises(ValueError):
        p["temperature"][0] = 1.0
    x0 = np.array(p["position"])
    with pytest.raises(RuntimeError, match="still referenced"):  # stepping would leave them dangling
        run.step()
    del p, again
    run.step(3)
    moved = run.particles["position"]
    assert np.all(moved[:, 0] > x0[:, 0])  # the block moves right at 1 m/s
    del moved
    run.finish()


def test_particle_field_units_cover_every_field():
    units = mpmcut.particle_field_units
    assert set(units) == set(mpmcut.particle_fields)
    assert units["temperature"] == "K" and units["stress"] == "Pa" and units["velocity"] == "m_per_s"
    assert units["mass"] == "kg_per_m" and units["plastic_strain"] == "" and units["body"] == "id"


def test_an_exception_in_the_callback_stops_the_run_and_its_summary_names_it(tmp_path):
    def boom(run):
        if run.step_count >= 2:
            raise ValueError("boom")

    run = mpmcut.Run(mpmcut.case_from_toml(ELASTIC), tmp_path / "r", threads=1)
    with pytest.raises(ValueError, match="boom"):
        run.run(boom)
    assert run.status == "interrupted"
    # It said "stopped on request (a stop signal, or a stop asked by the program driving the run)".
    assert run.summary()["message"].startswith("stopped on request: the callback raised ValueError: boom at step 2"), \
        run.summary()["message"]


def test_a_second_run_into_a_directory_in_use_is_refused_until_the_first_finishes(tmp_path):
    # A second Run with force=True used to wipe the directory while the first still wrote into it.
    case = mpmcut.case_from_toml(ELASTIC)
    first = mpmcut.Run(case, tmp_path / "r", threads=1)
    first.step(2)
    with pytest.raises(RuntimeError, match="is in use"):
        mpmcut.Run(case, tmp_path / "r", force=True, threads=1)
    assert (tmp_path / "r" / "history.csv").exists()
    first.finish()
    # Refusals name Run's arguments, not the command line's options.
    with pytest.raises(RuntimeError, match=r"already exists; use force=True to overwrite") as refused:
        mpmcut.Run(case, tmp_path / "r", threads=1)
    assert "--force" not in str(refused.value)
    second = mpmcut.Run(case, tmp_path / "r", force=True, threads=1)  # free once the first has finished
    second.finish()


def test_analyze_waits_for_the_run_writing_into_its_directory(tmp_path, binary, quick_case, short):
    # analyze merged an early snapshot's chip into a live run's summary.json.
    run = mpmcut.Run(mpmcut.load_case(quick_case, short), tmp_path / "r", threads=1)
    run.step(5)
    p = subprocess.run([binary, "analyze", str(tmp_path / "r")], capture_output=True, text=True)
    assert p.returncode == 4 and "is in use" in p.stderr and "once that run has finished" in p.stderr, p.stderr
    p = subprocess.run([binary, "resume", str(tmp_path / "r")], capture_output=True, text=True)  # exit 4 as for run
    assert p.returncode == 4 and "cannot resume" in p.stderr and "is in use" in p.stderr, p.stderr
    assert run.run() == "complete"
    p = subprocess.run([binary, "analyze", str(tmp_path / "r")], capture_output=True, text=True)
    assert p.returncode == 0, p.stderr


@pytest.mark.parametrize("threads", [-1, 1025, 100000])
def test_a_thread_count_out_of_range_is_an_error_not_a_crash(tmp_path, threads):
    with pytest.raises(Exception, match="threads = .*expected 1 to 1024"):
        mpmcut.Run(mpmcut.case_from_toml(ELASTIC), tmp_path / "r", threads=threads)


def test_stop_checkpoint_and_resume_continue_the_same_run(tmp_path, quick_case, short):
    case = mpmcut.load_case(quick_case, short)
    whole = mpmcut.run_case(case, tmp_path / "whole", threads=1)

    def stop_at_60(run):
        return run.step_count < 60

    stopped = mpmcut.run_case(case, tmp_path / "stopped", threads=1, callback=stop_at_60)
    assert stopped.status == "interrupted" and stopped.exit_code == 130
    assert stopped.summary()["last_checkpoint"].startswith("checkpoints/")
    # Stopped by the caller, not by a signal: the message says which (it said "a stop signal, or ...").
    assert stopped.summary()["message"].startswith("stopped on request: the callback returned False at step 60")
    resumed = mpmcut.Run.resume(tmp_path / "stopped", threads=1)
    assert resumed.step_count == 60
    assert resumed.run() == "complete"
    for name in ("forces.csv", "history.csv"):
        assert (tmp_path / "stopped" / name).read_bytes() == (whole.out / name).read_bytes(), name
    # An explicit checkpoint in the middle of a stepped run.
    run = mpmcut.Run(case, tmp_path / "explicit", threads=1)
    run.step(20)
    assert run.checkpoint().exists()
    run.stop()
    assert run.run() == "interrupted"
    early = mpmcut.Run(case, tmp_path / "early", threads=1)
    early.step(10)
    assert early.finish() == "interrupted"
    assert early.summary()["message"].startswith("ended by the caller before the end time at step 10")
    assert run.summary()["message"].startswith("stopped on request: Run.stop() at step 20")
    # A finished run takes no checkpoint: it would be newer than the summary it contradicts.
    for finished in (run, resumed):
        with pytest.raises(RuntimeError, match="the run has finished"):
            finished.checkpoint()


def test_the_gil_is_released_while_stepping(tmp_path, quick_case, short):
    import threading
    import time
    run = mpmcut.Run(mpmcut.load_case(quick_case, short), tmp_path / "r", threads=1)
    stepper = threading.Thread(target=run.step, args=(150,))
    start = last = time.perf_counter()
    longest = 0.0
    stepper.start()
    while stepper.is_alive():  # this thread runs only while the stepping one has let go of the GIL
        now = time.perf_counter()
        longest, last = max(longest, now - last), now
    total = time.perf_counter() - start
    stepper.join()
    # Held through the steps, the GIL would stop this loop for about the whole stepping time.
    assert run.step_count == 150 and longest < 0.5 * total, (longest, total)
    run.finish()


def test_one_thread_steps_a_run_at_a_time(tmp_path, quick_case, short):
    # Stepping one run from two threads corrupted it (non-finite velocities within 8-400 steps, "failed"): while one
    # thread steps, another's step, checkpoint, particle views and CSVs are refused; the run itself is untouched.
    import threading
    run = mpmcut.Run(mpmcut.load_case(quick_case, short), tmp_path / "r", threads=1)
    stepper = threading.Thread(target=run.step, args=(150,))
    stepper.start()
    refused = {}
    while stepper.is_alive():
        for name, call in (("step", lambda: run.step(1)), ("checkpoint", run.checkpoint),
                           ("particles", lambda: run.particles), ("forces", run.forces), ("summary", run.summary)):
            try:
                call()
            except RuntimeError as e:
                assert "being stepped by another thread" in str(e), e
                refused[name] = refused.get(name, 0) + 1
    stepper.join()
    # summary() walks the particle arrays, which a step reorders and frees: refused too (it raced).
    assert set(refused) == {"step", "checkpoint", "particles", "forces", "summary"}, refused
    assert run.step_count >= 150  # the refused calls did not step it; the others stepped between its steps
    assert run.run() == "complete"
    # Nonsense counts are refused, not ignored.
    with pytest.raises(ValueError, match="n must be 0 or more"):
        run.step(-5)
    with pytest.raises(ValueError, match="every must be 1 or more"):
        mpmcut.run_case(mpmcut.load_case(quick_case, short), tmp_path / "every", threads=1, every=0)


@pytest.mark.parametrize("where", ["callback", "step"])
def test_ctrl_c_stops_cleanly_then_raises(tmp_path, quick_case, where):
    import os
    import signal
    import threading
    run = mpmcut.Run(mpmcut.load_case(quick_case), tmp_path / "r", threads=1)

    def interrupt_in_callback(r):
        if r.step_count == 20:
            signal.raise_signal(signal.SIGINT)

    def interrupt_from_outside(r):
        if r.step_count == 20:  # arrives while the next steps run without the GIL
            threading.Thread(target=os.kill, args=(os.getpid(), signal.SIGINT)).start()

    with pytest.raises(KeyboardInterrupt):
        run.run(interrupt_in_callback if where == "callback" else interrupt_from_outside)
    assert run.status == "interrupted" and run.exit_code == 130
    # As the CLI's SIGINT says it (it read "ended by the caller", the words of an early finish()).
    assert run.summary()["message"].startswith("stopped on request: SIGINT (Ctrl-C)"), run.summary()["message"]
    assert 20 <= run.step_count < 17566  # stopped long before the end
    assert run.summary()["last_checkpoint"].startswith("checkpoints/")
    resumed = mpmcut.Run.resume(run.out, threads=1)
    assert resumed.step_count == run.step_count


def test_grid_convergence_reproduces_celik_2008_and_rejects_bad_grids():
    """The library's three-grid Richardson extrapolation, as `mpmcut convergence` uses it (Celik et al. 2008,
    Table 1: p = 1.53, extrapolated 6.1685, GCI 2.2 %)."""
    h = [n ** -0.5 for n in (18000, 8000, 4500)]
    e = mpmcut.grid_convergence(h[0], 6.063, h[1], 5.972, h[2], 5.863)
    assert e["behaviour"] == "monotonic" and e["order_plausible"]
    assert abs(e["observed_order"] - 1.53) < 0.005
    assert abs(e["extrapolated"] - 6.1685) < 0.0005
    assert abs(e["gci_fine"] - 0.022) < 0.0005
    osc = mpmcut.grid_convergence(1.0, 100.0, 1.5, 104.0, 2.25, 98.0)
    assert osc["behaviour"] == "oscillatory" and osc["observed_order"] is None
    with pytest.raises(ValueError):
        mpmcut.grid_convergence(2.0, 1.0, 1.0, 1.0, 4.0, 1.0)


def test_a_write_failure_raises_and_the_status_says_failed(tmp_path, quick_case, short):
    """Outputs that cannot be written (here: an 8 kB file-size limit, below the history and the final summary)
    came back as the status "running" from run(), with summary.json left at "running"."""
    import resource
    import sys
    script = f"""
import mpmcut
run = mpmcut.Run(mpmcut.load_case({str(quick_case)!r}, {dict(short, **{"output.vtu": False})!r}),
                 {str(tmp_path / "limited")!r}, threads=1)
try:
    run.run()
except RuntimeError as e:
    print("raised:", e)
print("status:", run.status, run.exit_code)
"""

    def limit_file_size():
        resource.setrlimit(resource.RLIMIT_FSIZE, (8 * 1024, 8 * 1024))

    done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, preexec_fn=limit_file_size,
                          timeout=300)
    assert "raised: Run: the results in" in done.stdout and "could not be written" in done.stdout, done
    assert "status: failed 4" in done.stdout, done


def test_objects_without_their_cpp_part_cannot_be_made():
    """Case.__new__(Case) and Run.__new__(Run) gave objects that crashed the interpreter when used."""
    with pytest.raises(TypeError, match="load_case"):
        mpmcut.Case.__new__(mpmcut.Case)
    with pytest.raises(TypeError, match="Run.resume"):
        mpmcut.Run.__new__(mpmcut.Run)
