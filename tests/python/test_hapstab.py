"""pytest for the Python package hapstab (python/): every function, exact inputs, errors, numpy
dtypes and shapes, and numbers identical to the command line's (`hapstab ... --json`).

Run: PYTHONPATH=build/python HAPSTAB_CLI=build/hapstab /usr/bin/python3 -m pytest tests/python
(ctest runs it as python_tests)."""
import json
import os
import signal
import subprocess
import sys
import textwrap
import time
from fractions import Fraction
from pathlib import Path

import numpy as np
import pytest

import hapstab

CLI = os.environ.get("HAPSTAB_CLI", "hapstab")
EXAMPLES = Path(hapstab.examples_dir())
WALL = "K + B*(z-1)/(T*z)"
KB = {"K": 1000, "B": 5}


def cli(*args):
    """`hapstab args... --json`: (exit code, JSON)."""
    p = subprocess.run([CLI, *args, "--json"], capture_output=True, text=True, check=False)
    assert p.returncode in (0, 1), p.stderr
    return p.returncode, json.loads(p.stdout)


# ---- the package ---------------------------------------------------------------------------

def test_import_from_the_build_tree():
    assert hapstab.__version__.count(".") == 2
    assert issubclass(hapstab.InputError, ValueError)
    assert issubclass(hapstab.NumericalError, RuntimeError)
    assert (Path(hapstab.__file__).parent / "py.typed").exists()
    assert (Path(hapstab.__file__).parent / "__init__.pyi").exists()
    assert (EXAMPLES / "002_bias_wall.toml").exists()


def test_import_without_the_extension_says_it_is_not_built(tmp_path):
    # the pure-Python files alone (a build folder before hapstab_python is built): a clear
    # ImportError naming what is missing, not a package without attributes (issue 31)
    package = tmp_path / "hapstab"
    package.mkdir()
    for f in Path(hapstab.__file__).parent.glob("*.py"):
        (package / f.name).write_text(f.read_text(encoding="utf-8"), encoding="utf-8")
    p = subprocess.run([sys.executable, "-c", "import hapstab"], capture_output=True, text=True, check=False,
                       env=dict(os.environ, PYTHONPATH=str(tmp_path)), cwd=tmp_path)  # not the build's python/
    assert p.returncode == 1
    assert "ImportError: hapstab: the C++ extension hapstab._core is not built in " + str(package) in p.stderr, p.stderr
    assert "cmake --build build --target hapstab_python" in p.stderr


def test_errors_speak_python():
    # the command's words (--set NAME=VALUE, --H, --frac-delay) become the call's (issue 31)
    with pytest.raises(hapstab.InputError) as e:
        hapstab.bound("K", T="1/1000")
    assert "unknown name 'K'" in str(e.value) and "pass params={'K': ...}" in str(e.value), str(e.value)
    assert "--" not in str(e.value)
    with pytest.raises(hapstab.InputError) as e:
        hapstab.bound(WALL, T="1/1000", params={"K": 1000})
    assert "pass params={'B': ...}" in str(e.value), str(e.value)
    with pytest.raises(hapstab.InputError) as e:
        hapstab.bound("1", T="1/1000", frac_delay=-1)
    assert str(e.value).startswith("frac_delay"), str(e.value)
    with pytest.raises(hapstab.InputError) as e:  # simulate's parameters are keyword arguments
        hapstab.simulate(EXAMPLES / "002_bias_wall.toml", out_of_range="1")
    assert "--" not in str(e.value), str(e.value)
    # the escape hatch keeps the command's words: it takes them
    with pytest.raises(hapstab.InputError, match="--set NAME=VALUE"):
        hapstab.run("bound", "--H", "K", "--T", "1/1000", "--json")


# ---- bound: the cases of paper 001 give the CLI's digits -----------------------------------

PAPER_001 = [
    # (H, T, delay, params, frac_delay, the value printed)
    (WALL, "1/1000", 0, KB, None, "5.5"),                     # (46): KT/2 + B
    (WALL, "1/1000", 1, KB, None, None),                      # (53): wall with delay n = 1
    (WALL, "1/1000", 1, {"K": 20000, "B": 5}, None, None),
    ("K + 2*B/T*(z-1)/(z+1)", "1/1000", 0, KB, None, "-4.5"),  # Tustin wall
    ("K + 2*B/T*(z-1)/(z+1)", "1/1000", 1, KB, None, "14.5"),  # Tustin wall, n = 1
    ("K + 2*B/T*(z-1)/(z+1)", "1/1000", 0, KB, "1/1000", "14.5"),  # t_d = T is n = 1
    ("(z-1)/(z+0.5)", "0.001", 0, {}, None, "0.002"),         # IIR (z-1)/(z+a)
    ("1/(z-1)", "1/1000", 0, {}, None, "inf"),                # integrator: no finite b
    ("(z-1)/(z^2-2*0.9999*0.8*z+0.9999^2)", "1/1000", 0, {}, None, None),  # narrow resonance
]


@pytest.mark.parametrize("H,T,delay,params,frac,value", PAPER_001)
def test_bound_gives_the_cli_digits(H, T, delay, params, frac, value):
    b = hapstab.bound(H, T=T, delay=delay, params=params, frac_delay=frac)
    args = ["bound", "--H", H, "--T", T, "--delay", str(delay)]
    args += [f"--set={k}={v}" for k, v in params.items()]
    if frac:
        args += ["--frac-delay", frac]
    code, j = cli(*args)
    assert b.as_dict() == j
    assert b.exit_code == code == 0
    assert b.value == j["bound"] and b.status == j["status"] and b.omega == j["omega"] and b.method == j["method"]
    assert b.enclosure == tuple(j["enclosure"])
    if value is not None:
        assert b.value == value
    if b.status == "exact" and b.value != "inf":
        assert b.fraction == Fraction(j["exact"])
        assert float(b) == float(b.fraction)
    else:
        assert b.fraction is None
    assert repr(b).startswith("hapstab.Bound(value=") and repr(j["status"]) in repr(b)


def test_bound_of_the_wall_is_kt2_plus_b_exactly():
    for K, B, T in [(1000, 5, Fraction(1, 1000)), (20000, 2, Fraction(1, 1000)), (300, Fraction(1, 3), Fraction(1, 7))]:
        b = hapstab.bound(WALL, T=T, params={"K": K, "B": B})
        assert b.fraction == K * T / 2 + B and b.status == "exact"


def test_bound_digits_method_eta_damping():
    H = "(z-1)/(z^2-2*0.9999*0.8*z+0.9999^2)"
    b = hapstab.bound(H, T="1/1000", digits=50)
    assert b.status == "certified" and len(b.value.replace("-", "").replace(".", "").split("e")[0]) >= 49
    lo, hi = (Fraction(x) for x in b.enclosure)  # the proven enclosure of b*; value is b* rounded
    assert lo <= hi and abs(Fraction(b.value) - lo) <= Fraction(1, 10**45) * abs(lo)
    assert hapstab.bound(H, T="1/1000", method="fast").status == "numeric"
    e = hapstab.bound(WALL, T="1/1000", params=KB, eta="1/2")
    assert e.as_dict() == cli("bound", "--H", WALL, "--T", "1/1000", "--set=K=1000", "--set=B=5", "--eta", "1/2")[1]
    assert hapstab.bound(WALL, T="1/1000", params={"K": 20000, "B": 2}, damping=11).exit_code == 1
    assert hapstab.bound(WALL, T="1/1000", params={"K": 20000, "B": 2}, damping="12.5").damping["passive"]


# ---- (num, den) and expression: the same exact result --------------------------------------

def test_num_den_and_expression_agree_exactly():
    # K + B(z-1)/(Tz) with K = 1000, B = 5, T = 1/1000 is (6000 z - 5000)/z
    ref = hapstab.bound(WALL, T="1/1000", params=KB, delay=1)
    for H in [([6000, -5000], [1, 0]),
              ((Fraction(6000), Fraction(-5000)), (1, 0)),
              (["6000", "-5e3"], ["1", "0"]),
              ([6000.0, -5000.0], [1.0, 0.0]),
              (np.array([6000, -5000], dtype=np.int64), np.array([1.0, 0.0])),
              ([[np.array([6000.0, -5000.0])]], [[np.array([1.0, 0.0])]])]:  # python-control's num[0][0]
        b = hapstab.bound(H, T="1/1000", delay=1)
        assert b.fraction == ref.fraction and b.as_dict() == ref.as_dict(), H


def test_floats_are_taken_at_their_exact_binary_value():
    # H = 0.1 (a constant): b* = T H / 2 with the double nearest 0.1, not 1/10
    b = hapstab.bound(([0.1], [1]), T=1)
    e = hapstab.bound(str(Fraction(0.1)), T=1)
    assert b.fraction == e.fraction == Fraction(0.1) / 2 != Fraction(1, 20)
    assert hapstab.bound((["0.1"], [1]), T=1).fraction == Fraction(1, 20)
    # T as a float is exact too: 1/1024 is a binary fraction
    assert hapstab.bound(WALL, T=1 / 1024, params=KB).fraction == Fraction(1000, 2048) + 5


class TransferFunctionLike:
    """What hapstab reads of a python-control TransferFunction: num[0][0], den[0][0], dt."""

    def __init__(self, num, den, dt):
        self.num, self.den, self.dt = [[np.array(num, dtype=float)]], [[np.array(den, dtype=float)]], dt


def test_a_python_control_transfer_function():
    sys_ = TransferFunctionLike([6.0, -5.0], [1.0, 0.0], 1 / 1024)
    b = hapstab.bound(sys_)  # T from dt, exactly
    assert b.fraction == hapstab.bound("(6*z - 5)/z", T="1/1024").fraction
    assert hapstab.bound(sys_, T="1/1024").fraction == b.fraction  # T matching dt
    with pytest.raises(hapstab.InputError, match="does not match"):
        hapstab.bound(sys_, T="1/1000")
    with pytest.raises(hapstab.InputError, match="continuous"):
        hapstab.bound(TransferFunctionLike([1.0], [1.0, 1.0], 0))
    with pytest.raises(hapstab.InputError, match="pass T"):
        hapstab.bound(TransferFunctionLike([1.0], [1.0, 0.5], True))
    assert hapstab.bound(TransferFunctionLike([1.0], [1.0, 0.5], True), T="1/100").status == "exact"


# ---- errors ---------------------------------------------------------------------------------

@pytest.mark.parametrize("call,match", [
    (lambda: hapstab.bound("K + (", T=1), "^H: "),                     # malformed expression (the keyword H)
    (lambda: hapstab.bound("z/(z-2)", T=1), "unstable"),               # H not stable
    (lambda: hapstab.bound("1", T=0), "^T: "),
    (lambda: hapstab.bound("1"), "T is required"),
    (lambda: hapstab.bound("1", T=1, eta=-1), "^eta"),
    (lambda: hapstab.bound(([1, "abc"], [1]), T=1), "not an exact number"),
    (lambda: hapstab.bound(([1, float("nan")], [1]), T=1), "finite"),
    (lambda: hapstab.bound(([], [1]), T=1), "empty"),
    (lambda: hapstab.bound(([[1, 2], [3, 4]], [1]), T=1), "SISO"),
    (lambda: hapstab.bound(([True], [1]), T=1), "bool"),
    (lambda: hapstab.bound("1", T="1/0"), "^T"),
    (lambda: hapstab.bound("1", T=1, params={"K": "1; rm -rf /"}), "not an exact number"),
    (lambda: hapstab.r(T=1, omega=0), "omega"),
    (lambda: hapstab.passivity_level("1"), "T is required"),
    (lambda: hapstab.passivity_level("1", T=1, ss=([[1]], [[1]], [[1]], [[1]])), "exactly one"),
    (lambda: hapstab.passivity_level(ss=([[0.5]], [[1, 2]], [[1]], [[1]]), T="1/100"), "ss"),
    (lambda: hapstab.multidof.analyze("/nonexistent.toml"), "nonexistent"),
    (lambda: hapstab.simulate(EXAMPLES / "002_bias_wall.toml", out_of_range="1"), "out_of_range"),
])
def test_bad_input_raises_input_error(call, match):
    with pytest.raises(hapstab.InputError, match=match):
        call()


SCENE_DATA = Path(__file__).resolve().parents[1] / "scene" / "data"


@pytest.mark.parametrize("call,match", [
    # issue 29: a scene's misspelled name or unmodelled part is refused, never dropped
    (lambda: hapstab.simulate(SCENE_DATA / "bias_wall_contacts.toml"),
     r"bias_wall_contacts.toml:41: unknown section \[contacts\]; did you mean \[contact\]\?"),
    (lambda: hapstab.multidof.analyze(SCENE_DATA / "multidof_ops.toml"),
     "unknown key multidof.ops; did you mean multidof.osp"),
    (lambda: hapstab.multidof.analyze(SCENE_DATA / "multidof_contact.toml"),
     r"multidof analyze does not model \[contact\] .*`hapstab simulate` does"),
    (lambda: hapstab.multidof.design(SCENE_DATA / "multidof_contact.toml"), r"multidof design does not model \[contact\]"),
])
def test_scene_refusals_raise_input_error(call, match):
    with pytest.raises(hapstab.InputError, match=match):
        call()


def test_wrong_types_raise_type_error():
    with pytest.raises(TypeError):
        hapstab.bound(42, T=1)
    with pytest.raises(TypeError):
        hapstab.bound("1", T=object())
    with pytest.raises(TypeError):
        hapstab.multidof.analyze(3)


def _pi_times_10_to(n):
    """floor(pi 10^n) within a few units, by Machin's formula in integers."""
    def atan_inv(x):
        total, term, k, sign = 0, 10**n // x, 1, 1
        while term:
            total += sign * (term // k)
            term, k, sign = term // (x * x), k + 2, -sign
        return total
    return 16 * atan_inv(5) - 4 * atan_inv(239)


def test_numerical_error_is_a_runtime_error():
    # w T/2 within 1e-4100 of pi: r(jw) sits on its pole for 4000-digit intervals (exit 3)
    omega = Fraction(2 * _pi_times_10_to(4200), 10**4200)
    with pytest.raises(hapstab.NumericalError, match="too close to a multiple of pi"):
        hapstab.r(T=1, omega=omega, digits=5)
    p = subprocess.run([CLI, "r", "--T", "1", "--omega", f"{omega.numerator}/{omega.denominator}"],
                       capture_output=True, check=False)
    assert p.returncode == 3


def test_results_are_read_only_and_say_what_they_hold():
    b = hapstab.bound(WALL, T="1/1000", params=KB)
    with pytest.raises(AttributeError, match="keys: "):
        b.no_such_key
    with pytest.raises(AttributeError):
        b.status = "certified"
    d = b.as_dict()
    d["bound"] = "0"
    assert b.value == "5.5"  # as_dict is a copy
    assert "closed_form" in dir(b)


# ---- r, wedge, passivity level -------------------------------------------------------------

def test_r_gives_the_cli_digits():
    r = hapstab.r("1/1000", 100, digits=25, terms=50)
    assert r.as_dict() == cli("r", "--T", "1/1000", "--omega", "100", "--digits", "25", "--terms", "50")[1]
    assert r.re == "-0.0005"  # exact: -T/2
    z = complex(r)
    assert z.real == -0.0005 and z.imag == float(r.im)
    with pytest.raises(TypeError):
        float(r)
    assert hapstab.r(Fraction(1, 1000), 100.0).as_dict() == hapstab.r("1/1000", 100).as_dict()


def test_wedge_gives_the_cli_verdict():
    H = "0.5*(z+1)/(z^2-0.5*z)"
    w = hapstab.wedge(H)
    code, j = cli("wedge", "--H", H)
    assert w.as_dict() == j and w.exit_code == code == 0
    assert bool(w) and w.wedge["holds"]
    assert w.as_dict() == hapstab.wedge(([0.5, 0.5], [1, -0.5, 0])).as_dict()
    strong = hapstab.wedge("8*(z+1)/(z^2-0.5*z)")
    assert strong.exit_code == cli("wedge", "--H", "8*(z+1)/(z^2-0.5*z)")[0]


def test_passivity_level_from_h_and_from_state_space(tmp_path):
    v = hapstab.passivity_level("1 + 1/(z-0.5)", T="1/100")
    assert v.as_dict() == cli("passivity-level", "--H", "1 + 1/(z-0.5)", "--T", "1/100")[1]
    assert float(v) == pytest.approx(1 / 3) and v.status == "exact"
    ss = ([[0.5]], [[1]], [[1]], [[1]])  # the same system
    w = hapstab.passivity_level(ss=ss, T="1/100")
    f = tmp_path / "ss.json"
    f.write_text(json.dumps({"A": [[0.5]], "B": [[1]], "C": [[1]], "D": [[1]], "T": "1/100"}))
    assert w.as_dict() == cli("passivity-level", "--ss", str(f))[1]
    A = np.array([[0.5, 0.1], [0.0, 0.25]])
    mimo = hapstab.passivity_level(ss=(A, np.eye(2), np.eye(2), 2 * np.eye(2)), T=Fraction(1, 100), kind="isp")
    assert mimo.kind == "isp" and mimo.level is not None


# ---- multi-DOF (paper 000) -----------------------------------------------------------------

def _without_times(d):
    d = dict(d)
    d.pop("seconds", None)
    return d


def test_multidof_analyze_and_design_give_the_cli_verdicts():
    scene = EXAMPLES / "multidof_case_i_nominal.toml"
    a = hapstab.multidof.analyze(scene)
    code, j = cli("multidof", "analyze", "--scene", str(scene))
    assert _without_times(a.as_dict()) == _without_times(j) and a.exit_code == code
    assert bool(a) == j["stability_concluded"] and repr(a).startswith("hapstab.Analysis(verdict=")
    d = hapstab.multidof.design(EXAMPLES / "multidof_case_ii_perturbed.toml", duration=2)
    code, j = cli("multidof", "design", "--scene", str(EXAMPLES / "multidof_case_ii_perturbed.toml"), "--duration", "2")
    assert d.feasible == j["feasible"] and d.certified == j["certified"] and d.D_V == j["D_V"]
    A, B, C, D = d.V
    assert all(M.dtype == np.float64 for M in (A, B, C, D)) and D.shape == np.array(j["D_V"]).shape


def test_multidof_overrides_are_scene_parameters():
    scene = EXAMPLES / "multidof_case_i_nominal.toml"
    text = scene.read_text()
    name = next(line.split("=")[0].strip() for line in text.split("[parameters]")[1].splitlines()[1:]
                if "=" in line)
    a = hapstab.multidof.analyze(scene, **{name: "1/2"})
    j = cli("multidof", "analyze", "--scene", str(scene), f"--set={name}=1/2")[1]
    assert _without_times(a.as_dict()) == _without_times(j)


# ---- simulate: numpy arrays ----------------------------------------------------------------

def test_simulate_returns_numpy_arrays_identical_to_the_csv(tmp_path):
    scene = EXAMPLES / "002_bias_wall.toml"
    s = hapstab.simulate(scene, out=tmp_path / "py")
    code, j = cli("simulate", "--scene", str(scene), "--out", str(tmp_path / "cli"), "--quiet")
    assert _without_times(s.summary) == _without_times(j) and s.exit_code == code == 0
    assert s.diverged is False and s.limit_cycle is not None
    rows = s.samples["t"].shape[0]
    assert rows > 1000 and s.samples["t"].dtype == np.float64
    for q in ("x", "v", "u", "fh", "E_port", "E_act", "E_po", "storage"):
        assert s.samples[q].shape == (rows, 1) and s.samples[q].dtype == np.float64, q
    assert s.units == {"t": "s", "x": "m", "v": "m/s", "u": "N", "fh": "N", "E_port": "J", "E_act": "J",
                       "E_po": "J", "storage": "J"}
    csv = np.loadtxt(tmp_path / "cli" / "samples.csv", delimiter=",", skiprows=1)
    assert np.array_equal(csv[:, 0], s.samples["t"]) and np.array_equal(csv[:, 2], s.samples["v"][:, 0])
    assert set(s.fine) == {"t", "x", "v"} and s.fine["x"].shape == (s.fine["t"].shape[0], 1)
    assert s.out == str(tmp_path / "py") and (tmp_path / "py" / "plot.gp").exists()


def test_simulate_scene_text_overrides_and_several_dofs():
    text = textwrap.dedent("""\
        [scene]
        T = "1/1000"
        [parameters]
        K = "100"
        [[device]]
        name = "a"
        m = "1"
        b = "2"
        [[device]]
        name = "b"
        m = "1/2"
        b = "1"
        [environment]
        tf = [["K", "0"], ["0", "K"]]
        [[input]]
        type = "impulse"
        dof = "b"
        time = "0"
        magnitude = "1/100"
        [simulate]
        steps = 200
        """)
    s = hapstab.simulate(text)
    assert s.samples["v"].shape == (201, 2) and s.out is None
    stiff = hapstab.simulate(text, K=Fraction(400))
    assert not np.array_equal(stiff.samples["x"], s.samples["x"])
    assert s.fine is None and "samples=201x2" in repr(s)


# ---- the GIL is released, Ctrl-C stops a long call -----------------------------------------

LONG_SCENE = """
[scene]
T = "1/1000"
[[device]]
name = "d"
m = "1"
b = "10"
[environment]
tf = "100 + 2*(z-1)/(T*z)"
[[input]]
type = "impulse"
dof = "d"
time = "0"
magnitude = "1/1000"
[simulate]
steps = 2000000000
record_every = 0
energy = false
"""


def _children(pid):
    try:
        return [int(c) for c in Path(f"/proc/{pid}/task/{pid}/children").read_text().split()]
    except FileNotFoundError:
        return []


@pytest.mark.parametrize("to_group", [False, True])
def test_ctrl_c_stops_a_long_call(to_group):
    # two billion steps (about a minute of computing): SIGINT, sent while the forked child
    # computes, must end the call with KeyboardInterrupt, kill the child, and leave the module
    # usable; to_group: as a terminal's Ctrl-C does, to the parent and the child together
    code = (f"import hapstab\nprint('started', flush=True)\ntry:\n    hapstab.simulate({LONG_SCENE!r})\n"
            "    print('completed')\nexcept KeyboardInterrupt:\n    print('interrupted', flush=True)\n"
            "    print(hapstab.bound('1', T=1).value)\n")
    p = subprocess.Popen([sys.executable, "-c", code], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                         start_new_session=True)
    assert p.stdout.readline().strip() == "started"
    deadline = time.monotonic() + 60  # a hang guard, not a measurement
    while not _children(p.pid) and time.monotonic() < deadline:
        time.sleep(0.01)
    computing = _children(p.pid)
    assert computing, "the call never forked its child"
    time.sleep(0.2)
    if to_group:
        os.killpg(p.pid, signal.SIGINT)
    else:
        p.send_signal(signal.SIGINT)
    out, err = p.communicate(timeout=120)
    assert out.split() == ["interrupted", "0.5"], (out, err)
    assert p.returncode == 0, err
    assert not Path(f"/proc/{computing[0]}").exists()  # killed and reaped


def test_other_threads_run_while_hapstab_computes():
    import threading
    ticks = []
    stop = threading.Event()

    def ticker():
        while not stop.is_set():
            ticks.append(1)
            time.sleep(0.001)

    t = threading.Thread(target=ticker, daemon=True)
    t.start()
    try:
        before = len(ticks)
        hapstab.simulate(LONG_SCENE.replace("2000000000", "3000000"))
        during = len(ticks) - before
    finally:
        stop.set()
        t.join()
    assert during > 0  # the ticker ran during the call: the GIL was free


def test_run_is_the_escape_hatch():
    res = hapstab.run("bound", "--H", WALL, "--T", "1/1000", "--set", "K=1000", "--set", "B=5", "--json")
    assert res.bound == "5.5" and res.exit_code == 0


# ---- stability (issue 19) --------------------------------------------------------------------

def test_stability_max_equals_the_command_line():
    device = dict(plant="1/(m*s^2 + b*s)", H=WALL, T="1/1000", delay=2, params={"m": 1, "b": 1, "B": 2})
    s = hapstab.stability(**device, max="K", digits=25)
    code, j = cli("stability", "--plant", device["plant"], "--H", WALL, "--T", "1/1000", "--delay", "2",
                  "--set", "m=1", "--set", "b=1", "--set", "B=2", "--max", "K", "--digits", "25")
    assert code == 0 and s.exit_code == 0
    assert s.value == j["max"] and s.status == "certified" and s.crossing["at"] == "complex pair"
    assert bool(s)
    K = float(s)
    assert hapstab.stability(**{**device, "params": {**device["params"], "K": Fraction(K * 0.99)}}).stable is True
    above = hapstab.stability(**{**device, "params": {**device["params"], "K": Fraction(K * 1.01)}})
    assert above.stable is False and above.exit_code == 1 and not above


def test_stability_bad_input_raises():
    with pytest.raises(hapstab.InputError, match="strictly proper"):
        hapstab.stability("s", "1", T="1/1000")
