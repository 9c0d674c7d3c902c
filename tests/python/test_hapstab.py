"""pytest for the Python package hapstab (python/): a binding of the library (no command line
inside), so every number is checked against the command line's (`hapstab ... --json`, the same
library functions), the result protocol (value, lo/hi outward, exact strings, honest
comparisons), the vectorised calls against scalar calls, the threads against one thread, errors
in Python's words, and every numeric argument refusing what it cannot take (issue 40).

Run: PYTHONPATH=build/python HAPSTAB_CLI=build/hapstab /usr/bin/python3 -m pytest tests/python
(ctest runs it as python_tests)."""
import json
import math
import os
import signal
import subprocess
import sys
import tempfile
import textwrap
import time
from fractions import Fraction
from pathlib import Path

import numpy as np
import pytest

import hapstab
from clitools import CLI, F, block, cli

EXAMPLES = Path(hapstab.examples_dir())
WALL = "K + B*(z-1)/(T*z)"
KB = {"K": 1000, "B": 5}






# ---- the package ---------------------------------------------------------------------------

def test_import_from_the_build_tree():
    assert hapstab.__version__.count(".") == 2
    assert issubclass(hapstab.InputError, ValueError)
    assert issubclass(hapstab.NumericalError, RuntimeError)
    assert issubclass(hapstab.UndecidedComparison, ValueError)
    assert (Path(hapstab.__file__).parent / "py.typed").exists()
    assert (Path(hapstab.__file__).parent / "__init__.pyi").exists()
    assert (EXAMPLES / "002_bias_wall.toml").exists()
    assert hapstab.STATUS == ("exact", "certified", "numeric", "failed")


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


def test_the_binding_runs_no_command_line():
    # bound, r, stability, passivity_level, wedge, simulate, multidof: library calls (issue 41), not `hapstab ...`
    for name in ("bound", "bound_many", "bound_max", "bound_max_many", "r", "r_many", "stability", "stability_many",
                 "stability_scene", "stability_scene_many", "passivity_level", "passivity_level_many",
                 "passivity_level_ss", "wedge", "simulate", "tf_from_expression", "multidof_analyze", "multidof_design"):
        assert callable(getattr(hapstab._core, name)), name
    src = Path(hapstab.__file__).read_text(encoding="utf-8")
    for function in ("bound", "_bound_max", "stability", "_stability_scene"):
        body = src.split(f"def {function}(")[1].split("\ndef ")[0]
        assert "_core.run" not in body and "json.loads" not in body, function
    multidof = (Path(hapstab.__file__).parent / "multidof.py").read_text(encoding="utf-8")
    assert "_core.run" not in multidof and "json" not in multidof and "tempfile" not in multidof


# ---- errors in the words of the call ---------------------------------------------------------

def test_the_module_has_no_proofs_and_says_so():
    # the module leaves the proofs out (pip builds less); run("proofs") refuses, never "0 passed"
    for words in (["proofs", "--quiet"], ["reproduce", "--only", "001", "--out", "/tmp/hapstab-py-no-proofs"]):
        with pytest.raises(hapstab.InputError) as e:
            hapstab.run(*words)
        assert "built without the proofs" in str(e.value), str(e.value)


def test_errors_speak_python():
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
    with pytest.raises(hapstab.InputError) as e:  # a non-causal H: the keyword that allows it
        hapstab.bound("z", T="1/1000")
    assert "allow_noncausal=True" in str(e.value) and "--" not in str(e.value), str(e.value)
    with pytest.raises(hapstab.InputError) as e:  # the vectorised path words its points the same way
        hapstab.bound("K*Q", T="1/1000", params={"K": [1, 2]})
    assert "pass params={'Q': ...}" in str(e.value) and "--" not in str(e.value), str(e.value)
    # the escape hatch keeps the command's words: it takes them
    with pytest.raises(hapstab.InputError, match="--set NAME=VALUE"):
        hapstab.run("bound", "--H", "K", "--T", "1/1000", "--json")


def test_a_dict_spec_error_names_no_temporary_file():
    with pytest.raises(hapstab.InputError) as e:
        hapstab.sweep({"command": "bound", "args": {"H": "K", "T": "1/1000"}, "axes": {"K": {"from": "0"}}})
    assert "spec.toml" not in str(e.value) and "/tmp" not in str(e.value) and str(e.value).startswith("spec"), str(e.value)


# ---- bound: the cases of paper 001 give the CLI's numbers -------------------------------------

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
def test_bound_gives_the_cli_numbers(H, T, delay, params, frac, value):
    b = hapstab.bound(H, T=T, delay=delay, params=params, frac_delay=frac)
    args = ["bound", "--H", H, "--T", T, "--delay", str(delay)]
    args += [f"--set={k}={v}" for k, v in params.items()]
    if frac:
        args += ["--frac-delay", frac]
    code, j = cli(*args)
    assert code == 0
    assert b.decimal == j["bound"] and b.status == j["status"] and b.omega == j["omega"] and b.method == j["method"]
    assert (b.lo_exact, b.hi_exact) == tuple(j["enclosure"])  # the same outward decimals
    assert b.closed_form == (None if j["closed_form"] is None else b.closed_form) and \
        (b.closed_form is None or b.closed_form["name"] == j["closed_form"])
    if value is not None:
        assert b.decimal == value
    if b.infinite:
        assert b.value == math.inf and b.lo == b.hi == math.inf
    elif b.status == "exact":
        assert isinstance(b.value, Fraction) and b.value == F(j["exact"])
        assert float(b) == float(b.value) and b.lo <= b.value <= b.hi
    else:
        assert isinstance(b.value, float)
        # the floats are the decimals rounded outward: never inside them
        assert Fraction(b.lo) <= F(b.lo_exact) and Fraction(b.hi) >= F(b.hi_exact)
        assert b.lo <= b.value <= b.hi


def test_bound_of_the_wall_is_kt2_plus_b_exactly():
    for K, B, T in [(1000, 5, Fraction(1, 1000)), (20000, 2, Fraction(1, 1000)), (300, Fraction(1, 3), Fraction(1, 7))]:
        b = hapstab.bound(WALL, T=T, params={"K": K, "B": B})
        assert b.value == K * T / 2 + B and b.status == "exact"
        assert b.closed_form["equation"] == "(46)"


def test_bound_digits_method_eta_damping():
    H = "(z-1)/(z^2-2*0.9999*0.8*z+0.9999^2)"
    b = hapstab.bound(H, T="1/1000", digits=50)
    assert b.status == "certified" and len(b.decimal.replace("-", "").replace(".", "").split("e")[0]) >= 49
    lo, hi = F(b.lo_exact), F(b.hi_exact)  # the proven enclosure of b*, 55 digits
    assert lo <= hi and (hi - lo) <= Fraction(1, 10**45) * abs(lo)
    assert hapstab.bound(H, T="1/1000", method="fast").status == "numeric"
    e = hapstab.bound(WALL, T="1/1000", params=KB, eta="1/2")
    assert e.value == Fraction(6)
    assert e.decimal == cli("bound", "--H", WALL, "--T", "1/1000", "--set=K=1000", "--set=B=5", "--eta", "1/2")[1]["bound"]
    assert hapstab.bound(WALL, T="1/1000", params={"K": 20000, "B": 2}, damping=11).damping["passive"] is False
    assert hapstab.bound(WALL, T="1/1000", params={"K": 20000, "B": 2}, damping="12.5").damping["passive"]
    with pytest.raises(hapstab.NumericalError, match="inside the enclosure"):
        hapstab.bound(H, T="1/1000", damping=b.lo_exact, digits=10)


# ---- the result protocol ------------------------------------------------------------------------

def test_comparisons_are_decided_by_the_enclosure_or_raise():
    b = hapstab.bound(WALL, T="1/1000", params=KB)  # exactly 11/2
    assert b > 5 and b >= Fraction(11, 2) and b <= "5.5" and b < 6 and b == 5.5 and b != 5
    assert not (b < 5) and not (b > 6) and b == Fraction(11, 2)
    c = hapstab.bound("(z-1)/(z^2-2*0.9999*0.8*z+0.9999^2)", T="1/1000", digits=12)
    assert c.status == "certified" and c.lo < c.hi
    assert c > F(c.lo_exact) - Fraction(1, 10**20) and c < F(c.hi_exact) + Fraction(1, 10**20)
    mid = (F(c.lo_exact) + F(c.hi_exact)) / 2  # exactly inside the enclosure
    for op in ("<", "<=", ">", ">=", "=="):
        with pytest.raises(hapstab.UndecidedComparison, match="cannot decide b\\*"):
            eval(f"c {op} mid")
    assert (c > b) is True and (b < c) is True and (b >= c) is False  # Result against Result: enclosures apart
    inf = hapstab.bound("1/(z-1)", T="1/1000")
    assert inf > 10**100 and inf == math.inf and float(inf) == math.inf


def test_protocol_fields_display_and_read_only():
    b = hapstab.bound(WALL, T="1/1000", params=KB)
    assert (b.value, b.lo, b.hi, b.lo_exact, b.hi_exact, b.status) == (Fraction(11, 2), 5.5, 5.5, "5.5", "5.5", "exact")
    assert "closed form" in b.method or b.method
    assert "<table>" in b._repr_html_() and "11/2" in b._repr_html_()
    assert b._repr_latex_() == r"$b^* = \frac{11}{2}$ \quad (exact)"
    c = hapstab.bound("(z-1)/(z+0.5)", T="1/1000", delay=1)
    assert r"\in [" in c._repr_latex_() or c.status == "exact"
    d = b.as_dict()
    d["value"] = 0
    assert b.value == Fraction(11, 2)  # as_dict is a copy
    with pytest.raises(AttributeError):
        b.status = "certified"
    with pytest.raises(AttributeError, match="it has: value, lo, hi"):
        b.no_such_field
    assert repr(b).startswith("hapstab.Bound(value=Fraction(11, 2), lo=5.5, hi=5.5, status='exact'")


# ---- (num, den), TransferFunction and expression: the same exact result ----------------------

def test_num_den_tf_and_expression_agree_exactly():
    # K + B(z-1)/(Tz) with K = 1000, B = 5, T = 1/1000 is (6000 z - 5000)/z
    ref = hapstab.bound(WALL, T="1/1000", params=KB, delay=1)
    H = hapstab.tf(WALL, T="1/1000", params=KB)
    assert isinstance(H, hapstab.TransferFunction) and H.num == ["6000", "-5000"] and H.den == ["1", "0"] and H.T == "1/1000"
    for h in [H, ([6000, -5000], [1, 0]), ((Fraction(6000), Fraction(-5000)), (1, 0)), (["6000", "-5e3"], ["1", "0"]),
              ([6000.0, -5000.0], [1.0, 0.0]), (np.array([6000, -5000], dtype=np.int64), np.array([1.0, 0.0])),
              ([[np.array([6000.0, -5000.0])]], [[np.array([1.0, 0.0])]])]:  # python-control's num[0][0]
        b = hapstab.bound(h, T="1/1000", delay=1)
        assert (b.value, b.lo, b.hi, b.status, b.omega) == (ref.value, ref.lo, ref.hi, ref.status, ref.omega), h
    assert hapstab.bound(H, delay=1).value == ref.value  # T from the TransferFunction
    with pytest.raises(hapstab.InputError, match="built with T = 1/1000"):
        hapstab.bound(H, T="1/100")


def test_floats_are_read_as_their_shortest_decimal():
    # (issue 49) 0.1 is 1/10 as written; Fraction(0.1) asks for the binary value
    assert hapstab.bound(([0.1], [1]), T=1).value == Fraction(1, 20) == hapstab.bound((["0.1"], [1]), T=1).value
    b = hapstab.bound(([Fraction(0.1)], [1]), T=1)
    assert b.value == hapstab.bound(str(Fraction(0.1)), T=1).value == Fraction(0.1) / 2 != Fraction(1, 20)
    assert hapstab.bound(WALL, T=1 / 1024, params=KB).value == Fraction(1000, 2048) + 5


class TransferFunctionLike:
    """What hapstab reads of a python-control TransferFunction: num[0][0], den[0][0], dt."""

    def __init__(self, num, den, dt):
        self.num, self.den, self.dt = [[np.array(num, dtype=float)]], [[np.array(den, dtype=float)]], dt


def test_a_python_control_transfer_function():
    sys_ = TransferFunctionLike([6.0, -5.0], [1.0, 0.0], 1 / 1024)
    b = hapstab.bound(sys_)  # T from dt, exactly
    assert b.value == hapstab.bound("(6*z - 5)/z", T="1/1024").value
    assert hapstab.bound(sys_, T="1/1024").value == b.value
    with pytest.raises(hapstab.InputError, match="does not match"):
        hapstab.bound(sys_, T="1/1000")
    with pytest.raises(hapstab.InputError, match="continuous"):
        hapstab.bound(TransferFunctionLike([1.0], [1.0, 1.0], 0))
    with pytest.raises(hapstab.InputError, match="pass T"):
        hapstab.bound(TransferFunctionLike([1.0], [1.0, 0.5], True))
    assert hapstab.bound(TransferFunctionLike([1.0], [1.0, 0.5], True), T="1/100").status == "exact"


# ---- vectorised calls ----------------------------------------------------------------------------

def test_bound_over_a_k_array_equals_scalar_calls():
    K = np.linspace(0, 40000, 41) * 1.0001 + 0.3  # not only round stiffnesses: certified points too
    bs = hapstab.bound(WALL, T="1/1000", delay=1, params={"K": K, "B": 5})
    assert isinstance(bs, hapstab.ResultArray) and bs.shape == (41,) and len(bs) == 41 and bs.failed == 0
    assert bs.value.dtype == bs.lo.dtype == bs.hi.dtype == bs.omega.dtype == np.float64 and bs.status.dtype.kind == "U"
    kinds = set()
    for i in range(41):
        one = hapstab.bound(WALL, T="1/1000", delay=1, params={"K": K[i], "B": 5})
        kinds.add(one.status)
        assert (bs.lo[i], bs.hi[i], bs.value[i]) == (one.lo, one.hi, float(one)), i
        assert bs.status[i] == one.status
        assert (bs.exact[i] is None) == (one.status != "exact")
        assert bs[i].status == one.status and bs[i].lo == one.lo and bs[i].K == K[i]
    assert kinds == {"exact", "certified"}, kinds  # both kinds of point were compared
    assert np.array_equal(np.asarray(bs), bs.value)
    # elementwise comparisons, decided by each enclosure
    passive = bs < 5.5
    assert passive.dtype == bool and passive[0] and not passive[-1]
    fast = hapstab.bound(WALL, T="1/1000", delay=1, params={"K": K, "B": 5}, method="fast")
    with pytest.raises(hapstab.UndecidedComparison, match="cannot decide"):
        fast < fast.value  # each estimate lies inside its stated band
    table = bs.to_table()
    assert table.dtype.names[:4] == ("K", "value", "lo", "hi") and table["status"].dtype.kind == "U"


def test_arrays_broadcast_and_keep_their_shape():
    K = np.array([0, 1000, 20000])
    B = np.array([[0], [5]])
    bs = hapstab.bound(WALL, T="1/1000", params={"K": K, "B": B})  # no delay: exact KT/2 + B
    assert bs.shape == (2, 3)
    expected = np.array([[F(str(k)) / 2000 + b for k in K] for b in (0, 5)], dtype=object)
    assert all(F(bs.exact[i, j]) == expected[i, j] for i in range(2) for j in range(3))
    assert (bs.status == "exact").all() and bs[1, 2].value == Fraction(15)
    # the same as lists, and as exact strings / Fractions (an object array)
    again = hapstab.bound(WALL, T="1/1000", params={"K": [0, 1000, 20000], "B": [["0"], [Fraction(5)]]})
    assert np.array_equal(again.value, bs.value) and list(again.exact.ravel()) == list(bs.exact.ravel())
    with pytest.raises(hapstab.InputError, match="do not broadcast"):
        hapstab.bound(WALL, T="1/1000", params={"K": [1, 2, 3], "B": [1, 2]})
    with pytest.raises(hapstab.InputError, match=r"params\['K'\]\[1\]: nan is not a finite"):
        hapstab.bound(WALL, T="1/1000", params={"K": [1.0, float("nan")], "B": 1})
    with pytest.raises(hapstab.InputError, match="expression string"):
        hapstab.bound(([1], [1, 0]), T="1/1000", params={"K": [1, 2]})


def test_a_failing_point_is_a_row_not_an_exception():
    bs = hapstab.bound("1/(z-c)", T="1/1000", params={"c": ["1/2", "2", "-1/4"]})
    assert list(bs.status) == ["exact", "failed", "exact"]
    assert bs.failed == 1 and "unstable" in bs.error[1] and bs.error[0] is None
    assert math.isnan(bs.value[1]) and bs.value[0] == float(hapstab.bound("1/(z-0.5)", T="1/1000"))
    with pytest.raises(hapstab.UndecidedComparison, match="the point failed"):
        bs < 100


def test_threads_give_the_serial_results_exactly():
    # a campaign over 2000 values of K (exact and certified points of the delayed wall): the
    # threaded run equals the one-thread run bit for bit, and each kind is compared at least
    # MIN times (a regression that made every point exact would fail here)
    MIN = 200
    K = np.linspace(1, 60000, 2000)
    one = hapstab.bound(WALL, T="1/1000", delay=1, params={"K": K, "B": 3}, jobs=1)
    two = hapstab.bound(WALL, T="1/1000", delay=1, params={"K": K, "B": 3}, jobs=2)
    for f in ("value", "lo", "hi", "status", "omega"):
        assert np.array_equal(getattr(one, f), getattr(two, f), equal_nan=f != "status"), f
    assert list(one.exact) == list(two.exact)
    counts = {s: int((one.status == s).sum()) for s in ("exact", "certified")}
    assert min(counts.values()) >= MIN, counts
    fast1 = hapstab.bound(WALL, T="1/1000", delay=1, params={"K": K, "B": 3}, method="fast", jobs=1)
    fast2 = hapstab.bound(WALL, T="1/1000", delay=1, params={"K": K, "B": 3}, method="fast", jobs=2)
    assert np.array_equal(fast1.value, fast2.value) and (fast1.status == "numeric").sum() >= MIN
    # the fast path within its stated error of the certified value (13 digits, bound.hpp)
    cert = one.value
    assert np.all(np.abs(fast1.value - cert) <= 1e-12 * np.maximum(1, np.abs(cert)))


def test_r_scalar_gives_the_cli_digits():
    r = hapstab.r("1/1000", 100, digits=25, terms=50)
    j = cli("r", "--T", "1/1000", "--omega", "100", "--digits", "25", "--terms", "50")[1]
    assert r.decimal == (j["re"], j["im"]) and r.series_im == j["series_im"]
    assert r.series_error_bound == j["series_error_bound"]
    assert r.re.value == Fraction(-1, 2000) and r.re.status == "exact" and r.im.status == "certified"
    assert F(r.im.lo_exact) <= F(j["im"]) <= F(r.im.hi_exact)
    z = complex(r)
    assert z.real == -0.0005 and z.imag == float(j["im"])
    with pytest.raises(TypeError):
        float(r)
    assert hapstab.r(Fraction(1, 1000), 100.0).decimal == hapstab.r("1/1000", 100).decimal


@pytest.mark.parametrize("T, w, digits", [("1/1000", "100", 20), ("1/1000", "6283", 30), ("1/3", "-7/5", 12),
                                          ("1/1000", "1/1000000", 40), ("1", "3", 25)])
def test_a_scalar_r_is_the_closed_form_alone_unless_terms_asks_for_the_series(T, w, digits):
    # issue 49: the default is what a scalar call needs, r(jw) = T/(e^{jwT} - 1) (44) correctly rounded;
    # the series (34) is summed only with terms=N, and the closed form's digits are the same either way
    plain = hapstab.r(T, w, digits=digits)
    both = hapstab.r(T, w, digits=digits, terms=1000)
    assert plain.series_re is None and plain.series_im is None and plain.series_terms is None
    assert plain.series_error_bound is None
    assert both.series_terms == 1000 and both.series_re is not None and both.series_im is not None
    assert plain.decimal == both.decimal and plain.status == both.status and plain.method == both.method
    for part in ("re", "im"):
        a, b = getattr(plain, part), getattr(both, part)
        assert (a.lo_exact, a.hi_exact, a.status, a.value) == (b.lo_exact, b.hi_exact, b.status, b.value)
    # against mpmath at twice the digits (shares no code with hapstab): the enclosure holds it
    mpmath = pytest.importorskip("mpmath")
    mpmath.mp.dps = 2 * digits + 20
    Tq, wq = F(T), F(w)
    Tm = mpmath.mpf(Tq.numerator) / Tq.denominator
    wm = mpmath.mpf(wq.numerator) / wq.denominator
    ref = Tm / (mpmath.exp(1j * wm * Tm) - 1)
    assert plain.re.value == -Tq / 2 and plain.re.status == "exact"
    lo, hi = (mpmath.mpf(F(x).numerator) / F(x).denominator for x in (plain.im.lo_exact, plain.im.hi_exact))
    assert lo <= ref.imag <= hi
    cli_json = cli("r", "--T", T, "--omega", w, "--digits", str(digits))[1]
    assert plain.decimal == (cli_json["re"], cli_json["im"])


def test_r_arrays_double_and_certified_against_30_digit_references():
    # wT over [1e-9, 2 pi) and the hard places: w -> 0, wT -> pi, just below 2 pi (near a pole)
    T = 1e-3
    wT = np.concatenate([np.geomspace(1e-9, 1, 60), np.linspace(1, 6.28, 60), [math.pi, math.pi * (1 - 1e-12),
                                                                              2 * math.pi * (1 - 1e-9)]])
    w = wT / T
    d = hapstab.r(T, w)
    c = hapstab.r(T, w, method="certified")
    assert d.status == "numeric" and c.status == "certified" and d.im.shape == w.shape
    compared = 0
    for i in range(0, len(w), 3):
        ref = hapstab.r(T, Fraction(float(w[i])), digits=30)  # correctly rounded, 30 digits, at w's binary value
        im = F(ref.decimal[1])
        assert Fraction(c.im_lo[i]) <= im <= Fraction(c.im_hi[i]), i           # proven enclosure
        assert abs(Fraction(d.im[i]) - im) <= Fraction(d.im_hi[i] - d.im_lo[i]) / 2 + abs(im) * Fraction(1, 10**28), i
        # the double value: within 1.51 eps of Im for the rounded theta, plus theta's rounding (r_forms.hpp)
        compared += 1
    assert compared >= 40
    assert d.re == -T / 2 and d.re_exact == str(-Fraction(T) / 2).replace(" ", "") or d.re_exact
    with pytest.raises(hapstab.InputError, match=r"omega\[1\]: 0\.0.* pole"):
        hapstab.r(T, [1.0, 0.0])


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
    (lambda: hapstab.bound("1 + K", T=1, params={"K": "1; rm -rf /"}), "not an exact number"),
    (lambda: hapstab.bound("1", T=1, method="exact"), "^method"),
    (lambda: hapstab.r(T=1, omega=0), "^omega"),
    (lambda: hapstab.passivity_level("1"), "T is required"),
    (lambda: hapstab.passivity_level("1", T=1, ss=([[1]], [[1]], [[1]], [[1]])), "exactly one"),
    (lambda: hapstab.passivity_level(ss=([[0.5]], [[1, 2]], [[1]], [[1]]), T="1/100"), "^ss"),
    (lambda: hapstab.passivity_level("1/(z-2)", T="1/100"), "^H: pole at z = 2"),
    (lambda: hapstab.passivity_level("1/(z-0.5)", T="1/100", backend="mosek"), "^backend"),
    (lambda: hapstab.stability("s", "1", T="1/1000"), "strictly proper"),
    (lambda: hapstab.stability("1/s^2", "K*Q", T="1/1000", max="K"), "pass params={'Q': ...}"),
    (lambda: hapstab.multidof.analyze("/nonexistent.toml"), "nonexistent"),
    (lambda: hapstab.simulate(EXAMPLES / "002_bias_wall.toml", out_of_range="1"), "out_of_range"),
])
def test_bad_input_raises_input_error(call, match):
    with pytest.raises(hapstab.InputError, match=match) as e:
        call()
    assert " --" not in str(e.value) and not str(e.value).startswith("--"), str(e.value)


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


# issue 40: every numeric argument refuses a bool, a non-integer where an integer is meant, and
# NaN / inf / <= 0 where a positive number is meant -- never truncates (delay=2.9 was delay 2)
NUMERIC_ARGUMENTS = [
    ("bound", "delay", lambda v: hapstab.bound(WALL, T="1/1000", params=KB, delay=v)),
    ("bound", "digits", lambda v: hapstab.bound(WALL, T="1/1000", params=KB, digits=v)),
    ("bound", "grid_points", lambda v: hapstab.bound(WALL, T="1/1000", params=KB, method="grid", grid_points=v)),
    ("bound", "jobs", lambda v: hapstab.bound(WALL, T="1/1000", params={"K": [1, 2], "B": 1}, jobs=v)),
    ("r", "digits", lambda v: hapstab.r("1/1000", 100, digits=v)),
    ("r", "terms", lambda v: hapstab.r("1/1000", 100, terms=v)),
    ("r", "jobs", lambda v: hapstab.r("1/1000", [100.0], jobs=v)),
    ("stability", "delay", lambda v: hapstab.stability("1/s^2", WALL, T="1/1000", params=KB, delay=v)),
    ("stability", "digits", lambda v: hapstab.stability("1/s^2", WALL, T="1/1000", params=KB, digits=v)),
    ("wedge", "digits", lambda v: hapstab.wedge("0.5*(z+1)/(z^2-0.5*z)", digits=v)),
    ("passivity_level", "lemma", lambda v: hapstab.passivity_level("1/(z-0.5)", T="1/100", lemma=v)),
    ("passivity_level", "grid", lambda v: hapstab.passivity_level("1/(z-0.5)", T="1/100", grid=v)),
    ("passivity_level", "digits", lambda v: hapstab.passivity_level("1/(z-0.5)", T="1/100", digits=v)),
    ("sweep", "jobs", lambda v: hapstab.sweep({"command": "r", "args": {"T": "1"}, "axes": {"omega": {"values": ["1"]}}},
                                             jobs=v)),
    ("multidof.design", "iterations", lambda v: hapstab.multidof.design(EXAMPLES / "multidof_case_i_nominal.toml",
                                                                        iterations=v)),
]


@pytest.mark.parametrize("function,name,call", NUMERIC_ARGUMENTS, ids=[f"{f}.{n}" for f, n, _ in NUMERIC_ARGUMENTS])
@pytest.mark.parametrize("bad", [2.9, 1.5, 2.0, True, False, "2", Fraction(5, 2)])
def test_integer_arguments_refuse_what_is_not_an_integer(function, name, call, bad):
    with pytest.raises(hapstab.InputError, match=f"^{name}: expected an integer, got the") as e:
        call(bad)
    assert repr(bad) in str(e.value)


def test_delay_is_never_truncated_and_says_where_seconds_go():
    with pytest.raises(hapstab.InputError, match=r"^delay: expected an integer, got the float 2\.9; .*frac_delay"):
        hapstab.bound(WALL, T="1/1000", params=KB, delay=2.9)
    with pytest.raises(hapstab.InputError, match=r"^delay: -1 is outside \[0, 1000000\]"):
        hapstab.bound(WALL, T="1/1000", params=KB, delay=-1)
    # a numpy integer is an integer; the delay in seconds is frac_delay (t_d = 2T is n = 2)
    assert hapstab.bound(WALL, T="1/1000", params=KB, delay=np.int64(2)).value == \
        hapstab.bound(WALL, T="1/1000", params=KB, frac_delay="2/1000").value


@pytest.mark.parametrize("bad", [float("nan"), float("inf"), -1.0, 0, True, "5"])
def test_positive_real_arguments_refuse_nan_inf_and_bools(bad):
    with pytest.raises(hapstab.InputError, match="^max_output: "):
        hapstab.simulate(EXAMPLES / "002_bias_wall.toml", max_output=bad)
    with pytest.raises(hapstab.InputError, match="^duration: "):
        hapstab.multidof.design(EXAMPLES / "multidof_case_i_nominal.toml", duration=bad)


@pytest.mark.parametrize("name,call", [
    ("T", lambda v: hapstab.bound("1", T=v)), ("eta", lambda v: hapstab.bound("1", T=1, eta=v)),
    ("frac_delay", lambda v: hapstab.bound("1", T=1, frac_delay=v)), ("damping", lambda v: hapstab.bound("1", T=1, damping=v)),
    ("omega", lambda v: hapstab.r(1, v)), ("params['K']", lambda v: hapstab.bound("K", T=1, params={"K": v})),
])
@pytest.mark.parametrize("bad", [True, float("nan"), float("inf")])
def test_exact_arguments_refuse_bools_and_non_finite_values(name, call, bad):
    with pytest.raises(hapstab.InputError) as e:
        call(bad)
    assert str(e.value).startswith(name), str(e.value)


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


# ---- wedge, passivity level, stability -----------------------------------------------------------

def test_wedge_gives_the_cli_verdict():
    H = "0.5*(z+1)/(z^2-0.5*z)"
    w = hapstab.wedge(H)
    code, j = cli("wedge", "--H", H)
    assert bool(w) == (code == 0) and w.wedge["holds"] == j["wedge_holds"] and w.tsypkin["holds"] == j["tsypkin_holds"]
    assert F(w.lo_exact) <= F(j["wedge"]["margin_enclosure"][0]) or w.lo_exact == j["wedge"]["margin_enclosure"][0]
    assert w > 0 and w.wedge["margin"] > 0  # the criterion holds iff its margin is > 0
    assert hapstab.wedge(([0.5, 0.5], [1, -0.5, 0])).value == w.value
    strong = hapstab.wedge("8*(z+1)/(z^2-0.5*z)")
    assert bool(strong) == (cli("wedge", "--H", "8*(z+1)/(z^2-0.5*z)")[0] == 0)


def test_passivity_level_from_h_and_from_state_space(tmp_path):
    v = hapstab.passivity_level("1 + 1/(z-0.5)", T="1/100")
    j = cli("passivity-level", "--H", "1 + 1/(z-0.5)", "--T", "1/100")[1]
    assert v.status == j["status"] == "exact" and v.value == Fraction(1, 3) and v.lo <= 1 / 3 <= v.hi
    assert v.method == j["method"] and v.kind == "osp"
    w = hapstab.passivity_level(ss=([[0.5]], [[1]], [[1]], [[1]]), T="1/100")  # the same system
    f = tmp_path / "ss.json"
    f.write_text(json.dumps({"A": [[0.5]], "B": [[1]], "C": [[1]], "D": [[1]], "T": "1/100"}))
    jw = cli("passivity-level", "--ss", str(f))[1]
    assert w.status == jw["status"] and w.value == Fraction(1, 3)
    A = np.array([[0.5, 0.1], [0.0, 0.25]])
    mimo = hapstab.passivity_level(ss=(A, np.eye(2), np.eye(2), 2 * np.eye(2)), T=Fraction(1, 100), kind="isp")
    assert mimo.kind == "isp" and mimo.status in ("exact", "certified") and mimo.lo <= mimo.hi
    S = hapstab.ss(A, np.eye(2), np.eye(2), 2 * np.eye(2), Fraction(1, 100))
    assert S.shape == (2, 2, 2) and hapstab.passivity_level(ss=S, kind="isp").value == mimo.value


def test_passivity_level_over_an_array_equals_scalar_calls():
    a = np.array(["0.1", "0.5", "0.9", "-0.3"], dtype=object)
    v = hapstab.passivity_level("1 + 1/(z-a)", T="1/100", params={"a": a})
    assert v.shape == (4,) and v.failed == 0
    for i, x in enumerate(a):
        one = hapstab.passivity_level("1 + 1/(z-a)", T="1/100", params={"a": x})
        assert (v.lo[i], v.hi[i], v.status[i]) == (one.lo, one.hi, one.status), x


def test_stability_max_equals_the_command_line():
    device = dict(plant="1/(m*s^2 + b*s)", H=WALL, T="1/1000", delay=2, params={"m": 1, "b": 1, "B": 2})
    s = hapstab.stability(**device, max="K", digits=25)
    code, j = cli("stability", "--plant", device["plant"], "--H", WALL, "--T", "1/1000", "--delay", "2",
                  "--set", "m=1", "--set", "b=1", "--set", "B=2", "--max", "K", "--digits", "25")
    assert code == 0 and isinstance(s, hapstab.MaxGain)
    assert s.status == j["status"] == "certified" and s.crossing == j["crossing"]["at"] == "complex pair"
    assert (s.lo_exact, s.hi_exact) == tuple(j["enclosure"]) and bool(s)
    K = s.value
    below = hapstab.stability(**{**device, "params": {**device["params"], "K": Fraction(K * 0.99)}})
    above = hapstab.stability(**{**device, "params": {**device["params"], "K": Fraction(K * 1.01)}})
    assert below.stable is True and bool(below) and below < 1  # the spectral radius
    assert above.stable is False and not above and above > 1
    with pytest.raises(hapstab.UndecidedComparison):
        s == (F(s.lo_exact) + F(s.hi_exact)) / 2


def test_stability_over_arrays_equals_scalar_calls():
    K = np.array([100, 5000, 20000, 60000])
    st = hapstab.stability("1/(m*s^2 + b*s)", WALL, T="1/1000", delay=1, params={"m": 1, "b": 1, "B": 2, "K": K})
    for i, k in enumerate(K):
        one = hapstab.stability("1/(m*s^2 + b*s)", WALL, T="1/1000", delay=1, params={"m": 1, "b": 1, "B": 2, "K": k})
        assert st.stable[i] == (1 if one.stable else 0) and (st.lo[i], st.hi[i]) == (one.lo, one.hi)
    assert set(st.stable) == {0, 1}
    B = np.array([0, 2, 5])
    mx = hapstab.stability("1/(m*s^2 + b*s)", WALL, T="1/1000", delay=1, max="K", params={"m": 1, "b": 1, "B": B})
    for i, bb in enumerate(B):
        one = hapstab.stability("1/(m*s^2 + b*s)", WALL, T="1/1000", delay=1, max="K", params={"m": 1, "b": 1, "B": bb})
        assert (mx.lo[i], mx.hi[i]) == (one.lo, one.hi)


# ---- the passivity boundary as a number: bound(..., max="K") --------------------------------

def _sqrt_enclosure(n, digits=60):
    """[lo, hi] Fractions around sqrt(n), 10^-digits wide (integer square root: exact)."""
    import math as _m
    r = _m.isqrt(n * 10 ** (2 * digits))
    return Fraction(r, 10**digits), Fraction(r + 1, 10**digits)


def test_bound_max_equals_the_command_line_and_the_closed_form():
    # README's case: the one-sample-delay wall, B = 1/2, b = 3/2: K_max = (2 sqrt(B(2b - B)) - 2B)/T
    # = 1000 (sqrt(5) - 1), irrational; the reference is sqrt(5) to 60 digits in integers (more
    # than the 30 asked), and the enclosure must contain it and be at most 10^-29 relative wide
    m = hapstab.bound(WALL, T="1/1000", delay=1, params={"B": "1/2"}, damping="3/2", max="K", check=True)
    code, j = cli("bound", "--H", WALL, "--T", "1/1000", "--set", "B=1/2", "--delay", "1", "--damping", "3/2",
                  "--max", "K", "--explain")
    assert code == 0 and bool(m) and isinstance(m, hapstab.MaxPassiveGain)
    assert (m.lo_exact, m.hi_exact) == tuple(j["enclosure"]) and m.decimal == j["max"] and m.status == j["status"]
    lo5, hi5 = _sqrt_enclosure(5)
    assert F(m.lo_exact) <= 1000 * (hi5 - 1) and 1000 * (lo5 - 1) <= F(m.hi_exact)
    assert F(m.hi_exact) - F(m.lo_exact) <= Fraction(1236, 10**29)
    assert m.lo <= float(F(m.lo_exact)) and float(F(m.hi_exact)) <= m.hi  # the floats rounded outward
    assert m.closed_form["equation"] == "(53)" and m.closed_form["agrees"] and m.closed_form["value"] == j["closed_form_value"]
    assert m.check["holds"] and m.b_at_zero.value == Fraction(1, 2) and F(m.damping) == Fraction(3, 2)
    assert m.omega[0] <= m.omega[1] and m.where == "interior"  # where b* = b: the command's 17 digits
    assert m.omega == pytest.approx((float(j["omega"][0]), float(j["omega"][1])), rel=4 * 2**-52)
    # b* itself at the ends (an independent path: the maximiser of b*, 60 digits): <= b below, >= b above
    at = lambda K: hapstab.bound(WALL, T="1/1000", delay=1, params={"K": F(K), "B": "1/2"}, digits=60)  # noqa: E731
    assert at(m.lo_exact) < Fraction(3, 2) < at(m.hi_exact)
    assert m > 1236 and m < 1237 and float(m) == pytest.approx(1236.0679774997897, rel=2**-52)


def test_bound_max_exact_where_rational_and_at_the_edges():
    # no delay: K_max = 2(b - B)/T exactly (the backward-difference wall, (46)); the Tustin wall:
    # b* = KT/2 - B, K_max = 2(b + B)/T, its maximiser at omega T = pi (the band edge)
    m = hapstab.bound(WALL, T="1/1000", params={"B": "1/2"}, damping="3/2", max="K")
    assert m.status == "exact" and m.value == Fraction(2000) and m.lo == m.hi == 2000.0
    t = hapstab.bound("K + 2*B/T*(z-1)/(z+1)", T="1/1000", params={"B": "1/2"}, damping="3/2", max="K")
    assert t.value == Fraction(4000) and t.status == "exact"
    # not passive at K = 0 (b <= b*(0) = B): 0, and bool is False; passive for every K: inf
    z = hapstab.bound(WALL, T="1/1000", params={"B": 2}, damping="3/2", max="K")
    assert z.value == 0 and not z and z.outcome != "holds"
    # a negative stiffness lowers b* = B - KT/2 for every K: passive for every K >= 0
    inf = hapstab.bound("B*(z-1)/(T*z) - K", T="1/1000", params={"B": "1/2"}, damping="3/2", max="K")
    assert inf.infinite and math.isinf(inf.value) and bool(inf)
    code, j = cli("bound", "--H", "B*(z-1)/(T*z) - K", "--T", "1/1000", "--set", "B=1/2", "--damping", "3/2", "--max", "K")
    assert j["max"] == "inf" and code == 0
    # a jump of b* at the sup: H's residue at z = -1, 1 - K, changes sign at K = 1 under t_d = T/2, so
    # b*(1) = T/2 < b and b* = +inf above (the command's "jump"); a smooth crossing has no jump
    jm = hapstab.bound("(1-K)/(z+1)+1/2", T="1/1000", frac_delay="1/2000", max="K", damping=1)
    assert jm.value == 1 and jm.status == "exact" and jm.jump and jm.b_at_sup.value == Fraction(1, 2000)
    assert not m.jump and m.b_at_sup is None


def test_bound_max_over_arrays_equals_scalar_calls():
    # B and b as arrays (broadcast), delay 0: every point is 2(b - B)/T exactly where b > B, else
    # 0; delay 1: every point equals its scalar call's enclosure bit for bit (threads or not)
    B = np.linspace(0, 3, 61)
    b = np.array([[1.0], [2.5]])
    ms = hapstab.bound(WALL, T="1/1000", params={"B": B}, damping=b, max="K")
    assert ms.shape == (2, 61) and ms.failed == 0
    expected = np.maximum(2 * (b - B) * 1000, 0)
    compared = 0
    for idx in np.ndindex(ms.shape):
        if expected[idx] > 0:
            assert F(ms.exact[idx]) == Fraction(2) * (Fraction(repr(b[idx[0], 0])) - Fraction(repr(B[idx[1]]))) * 1000, idx  # floats: their shortest decimals
            compared += 1
        else:
            assert ms.value[idx] == 0, idx
    assert compared >= 60  # non-trivial (K_max > 0) points compared exactly
    Bd = np.linspace(0.1, 2, 40)
    md = hapstab.bound(WALL, T="1/1000", delay=1, params={"B": Bd}, damping="3/2", max="K", jobs=2)
    for i in range(0, 40, 3):
        one = hapstab.bound(WALL, T="1/1000", delay=1, params={"B": Bd[i]}, damping="3/2", max="K")
        assert (md.lo[i], md.hi[i], md.lo_exact[i], md.hi_exact[i]) == (one.lo, one.hi, one.lo_exact, one.hi_exact), i
        assert md.status[i] == one.status
        assert md.omega[i] == pytest.approx((one.omega[0] + one.omega[1]) / 2) if one.omega else np.isnan(md.omega[i])
    serial = hapstab.bound(WALL, T="1/1000", delay=1, params={"B": Bd}, damping="3/2", max="K", jobs=1)
    assert np.array_equal(serial.lo, md.lo) and np.array_equal(serial.hi, md.hi)


@pytest.mark.parametrize("call,match", [
    (lambda: hapstab.bound(WALL, T="1/1000", params={"B": 1}, max="K"), r"^max='K' needs damping=b"),
    (lambda: hapstab.bound(WALL, T="1/1000", params={"B": 1}, damping=2, max="K", method="fast"), "certified only"),
    (lambda: hapstab.bound("K^2 + B", T="1/1000", params={"B": 1}, damping=2, max="K"), "^max='K': H: .*affine"),
    (lambda: hapstab.bound(WALL, T="1/1000", params={"B": 1, "K": 2}, damping=2, max="K"), "maximised"),
    (lambda: hapstab.bound(WALL, T="1/1000", params={"B": 1}, damping=0, max="K"), "^damping must be > 0"),
    (lambda: hapstab.bound(WALL, T="1/1000", params={"B": [1, 2]}, damping=2, max="K", check=True), "^check"),
    (lambda: hapstab.bound(WALL, T="1/1000", params={"B": 1}, damping=[1, 2, 3], max="K"), None),
    (lambda: hapstab.bound(WALL, T="1/1000", params={"B": [1, 2]}, damping=[1, 2, 3], max="K"), "^damping: .*broadcast"),
    (lambda: hapstab.bound(WALL, T="1/1000", params=KB, check=True), "^check"),
    (lambda: hapstab.bound(WALL, T="1/1000", params={"B": 1}, damping=2, max="Q"), "Q"),
])
def test_bound_max_refuses_by_name(call, match):
    if match is None:  # a damping array alone is a vector call, not an error
        assert call().shape == (3,)
        return
    with pytest.raises(hapstab.InputError, match=match) as e:
        call()
    assert " --" not in str(e.value), str(e.value)


# ---- stability(scene=...): the loop as written, any number of DOF, hidden modes ------------

SCENES = Path(__file__).resolve().parents[1] / "cli" / "scenes"


@pytest.mark.parametrize("scene", [EXAMPLES / "000_two_dof_loop.toml", SCENES / "hand_3dof.toml",
                                   SCENES / "hidden_env.toml", SCENES / "hidden_device.toml",
                                   SCENES / "hidden_operator.toml", SCENES / "two_dof_diverging.toml"])
def test_stability_of_a_scene_is_the_commands_decision(scene):
    s = hapstab.stability(scene=scene)
    p = subprocess.run([CLI, "stability", "--scene", str(scene), "--json"], capture_output=True, text=True, check=False)
    assert p.returncode in (0, 1), p.stderr
    j = json.loads(p.stdout)
    assert s.stable == j["stable"] and s.verdict_status == j["status"] and s.decider == j["method"]
    assert s.evidence == j["evidence"] and s.dofs == j["dofs"] and s.states == j["states"]
    radius = j["spectral_radius_numeric"]  # null when a hidden mode decided (nothing computed): NaN in Python
    assert (math.isnan(s.value) if radius is None else s.value == radius) and s.status == "numeric"
    assert bool(s) == (p.returncode == 0)
    assert [(m["block"], m["kind"], m["where"], m["stable"]) for m in s.hidden_modes] == \
        [(m["block"], m["kind"], m["where"], m["stable"]) for m in j["hidden_modes"]]
    for m in s.hidden_modes:  # the enclosure of |z| (or Re s) decides the mode's stability
        assert m["abs"][0] <= m["abs"][1]
        if m["discrete"]:
            assert (m["abs"][1] < 1) if m["stable"] else (m["abs"][1] >= 1)


def test_stability_of_a_scene_over_parameter_arrays():
    # the 2-DOF loop of Sec. VI over the contact stiffness k1: each point equals its scalar call
    scene = EXAMPLES / "000_two_dof_loop.toml"
    k1 = np.array([50, 200, 1000, 5000, 20000, 100000])
    sa = hapstab.stability(scene=scene, params={"k1": k1})
    assert sa.shape == (6,) and sa.failed == 0
    compared = 0
    for i, k in enumerate(k1):
        one = hapstab.stability(scene=scene, params={"k1": int(k)})
        assert sa.stable[i] == {True: 1, False: 0, None: -1}[one.stable] and sa.value[i] == one.value
        assert sa.evidence[i] == one.evidence
        compared += one.stable is not None
    assert compared == 6 and set(sa.stable) == {0, 1}  # both verdicts met on this range
    assert sa[0].stable == 1 and bool(sa[0])


@pytest.mark.parametrize("call,match", [
    (lambda: hapstab.stability("1/s^2", scene=EXAMPLES / "000_two_dof_loop.toml"), "^scene replaces .*plant"),
    (lambda: hapstab.stability(scene=EXAMPLES / "000_two_dof_loop.toml", max="k1", params={"k1": [1, 2]}),
     "^max='k1' with scene: one point per call"),
    (lambda: hapstab.stability(scene=EXAMPLES / "000_two_dof_loop.toml", conservatism=True), "^conservatism=True .*max="),
    (lambda: hapstab.stability(scene=EXAMPLES / "multidof_case_ii_nominal.toml", max="k", conservatism=True),
     r"\[coupling\]"),
    (lambda: hapstab.stability(scene=EXAMPLES / "000_two_dof_loop.toml", params={"kk": 1}), "kk"),
    (lambda: hapstab.stability(scene=SCENE_DATA / "multidof_ops.toml"), "unknown key multidof.ops"),
    (lambda: hapstab.stability(), "^give plant and H"),
])
def test_stability_of_a_scene_refuses_by_name(call, match):
    with pytest.raises(hapstab.InputError, match=match) as e:
        call()
    assert " --" not in str(e.value).split("`")[0], str(e.value)


# ---- multi-DOF (paper 000) -----------------------------------------------------------------

def _same_checks(py_list, cli_list, keys):
    assert [{k: e[k] for k in keys} for e in py_list] == [{k: e[k] for k in keys} for e in cli_list]


@pytest.mark.parametrize("scene", ["multidof_case_i_nominal.toml", "multidof_case_ii_perturbed.toml"])
def test_multidof_analyze_is_the_commands_study(scene):
    # one library entry point (multidof::analyze_scene) behind both: every field the command
    # prints comes back, the same (floats bit for bit: the same computation, not a re-parse)
    a = hapstab.multidof.analyze(EXAMPLES / scene)
    code, j = cli("multidof", "analyze", "--scene", str(EXAMPLES / scene))
    assert a.verdict == j["verdict"] and a.certified == j["certified"] and a.feasible == j["feasible"]
    assert a.stability_concluded == j["stability_concluded"] and bool(a) == a.ok == (code == 0)
    assert a.value == j["margin"] and a.status == "certified" and a.certificate == j["certificate"]
    assert list(a.gamma) == j["gamma"] and np.array_equal(a.q_v, np.array(j["q_v"]))
    assert np.array_equal(a.delta_v_required, np.array(j["delta_v_required"])) and a.q_v.dtype == np.float64
    _same_checks(a.assumptions, j["assumptions"], ("name", "holds", "outcome", "certified", "detail"))
    law = j["loop_as_written"]
    assert {k: a.loop_as_written[k] for k in law} == law
    assert [(m["block"], m["kind"], m["where"], m["stable"]) for m in a.hidden_modes] == \
        [(m["block"], m["kind"], m["where"], m["stable"]) for m in j["hidden_modes"]]
    assert a.premise_failure == "" if a.premises_hold else a.premise_failure.startswith(("Assumption 1", "a premise"))
    assert set(a.seconds) == set(j["seconds"]) and a.dofs == 2


def test_multidof_reprs_say_which_loop_each_verdict_is_about():
    # issue 49: case ii nominal -- Theorem 5 concludes (for the loop with a coupling meeting (14)),
    # the scene's own loop (no coupling) is NOT stable, bool() is False: the repr says all three
    a = hapstab.multidof.analyze(EXAMPLES / "multidof_case_ii_nominal.toml")
    assert a.stability_concluded and not a.loop_as_written["stable"] and not a
    text = repr(a)
    assert "theorem5='stable: the loop with any coupling V whose V-hat^Gamma is Delta_V-OSP" in text, text
    assert "loop_as_written='NOT stable [certified], coupling: none (the direct connection)'" in text, text
    assert text.endswith("ok=False)") and "stability_concluded" not in text, text
    assert "loop_as_written" in a._repr_html_()
    # case i: no conclusion, and why
    b = hapstab.multidof.analyze(EXAMPLES / "multidof_case_i_nominal.toml")
    assert "theorem5=\"no conclusion: Assumption 1 fails" in repr(b), repr(b)


def test_multidof_design_is_the_commands_study():
    scene = EXAMPLES / "multidof_case_ii_perturbed.toml"
    d = hapstab.multidof.design(scene, duration=2)
    code, j = cli("multidof", "design", "--scene", str(scene), "--duration", "2")
    for k in ("feasible", "certified", "converged", "iterations", "trace_gap", "convex_infeasible", "convex_certified",
              "facial_reduction", "message", "warning"):
        assert getattr(d, k) == j[k], k
    assert bool(d) == d.ok == (code == 0) and d.value == j["trace_gap"] and d.status == "numeric"
    A, B, C, D = d.V
    for M, k in zip((A, B, C, D), ("A_V", "B_V", "C_V", "D_V")):
        assert M.dtype == np.float64 and np.array_equal(M, np.array(j[k])), k
    # the exact V the checks ran on: its doubles are the printed V
    assert isinstance(d.V_exact, hapstab.StateSpace)
    assert np.array_equal(np.array([[float(F(x)) for x in row] for row in d.V_exact.D]), D)
    _same_checks(d.verification, j["verification"], ("name", "certified", "detail"))
    assert [v["verdict"] for v in d.verification] == [v["verdict"].lower() for v in j["verification"]]
    assert d.verification[-1]["status"] == "numeric" and "simulated" in d.verification[-1]["name"]
    assert {k: d.loop_with_v[k] for k in j["loop_with_v"]} == j["loop_with_v"]
    assert d.simulation["decays"] is False and d.simulation["text"] in d.warning  # 2 s: slow decay, warned
    assert f"loop_with_v='stable [{d.loop_with_v['status']}], coupling: the designed V'" in repr(d), repr(d)
    _same_checks(d.assumptions, j["assumptions"], ("name", "holds", "outcome", "certified", "detail"))


def test_multidof_hidden_modes_and_premises():
    # a block hiding an unstable mode: the premise fails by name, the loop as written is NOT
    # stable (exact), and the mode is in the result with its location enclosed
    scene = SOURCE / "tests" / "cli" / "scenes" / "hidden_env.toml"
    code, j = cli("multidof", "analyze", "--scene", str(scene))
    a = hapstab.multidof.analyze(scene)
    assert not a and code == 1 and a.loop_as_written["stable"] is False and a.loop_as_written["status"] == "exact"
    assert not a.premises_hold and a.premise_failure.startswith("a premise fails"), a.premise_failure
    (m,) = a.hidden_modes
    assert (m["block"], m["kind"], m["where"], m["stable"]) == ("environment", "unobservable", "z = 2", False)
    assert m["abs"] == (2.0, 2.0) and m["re"] == (2.0, 2.0) and m["discrete"] is True


def _on_the_circle(z):
    re, im = (Fraction(x) for x in z)
    return re * re + im * im == 1


def test_multidof_witnesses_are_the_commands():
    # issue 46: the exact witnesses of infeasibility come back as `multidof analyze --json` prints
    # them (rationals as "p/q" strings): (16)'s one-frequency witness, and Theorem 4's two-frequency
    # witness for the scene's own coupling (loop_as_written)
    cli_scenes = Path(__file__).resolve().parents[1] / "cli" / "scenes"
    a = hapstab.multidof.analyze(cli_scenes / "witness_interior_wall.toml")
    code, j = cli("multidof", "analyze", "--scene", str(cli_scenes / "witness_interior_wall.toml"))
    assert a.path == j["path"] == "frequency-domain witness" and not a.feasible and a.certified
    assert a.witness == j["witness"] and a.weighted_witness is None and j["weighted_witness"] is None
    w = a.witness
    assert _on_the_circle(w["z"]) and any(Fraction(x) != 0 for x in w["u"]) and w["phi_negative"] and w["phi"] < 0
    b = hapstab.multidof.analyze(cli_scenes / "coupling_witness_linked_walls.toml")
    code, j = cli("multidof", "analyze", "--scene", str(cli_scenes / "coupling_witness_linked_walls.toml"))
    t4 = b.loop_as_written["theorem4_witness"]
    assert t4 is not None and t4 == j["loop_as_written"]["theorem4_witness"]
    assert _on_the_circle(t4["z1"]) and _on_the_circle(t4["z2"]) and len(t4["p"]["re"]) == len(t4["u"]["im"]) == b.dofs
    assert len(t4["phi"]) == len(t4["directions"]) >= 1 and all(Fraction(x) <= 0 for x in t4["phi"]) and t4["phi_nonpositive"]
    assert [float(Fraction(x)) for x in t4["phi"]] == pytest.approx(t4["phi_numeric"])
    assert "frequency-domain witness" in b.loop_as_written["why"]
    # Theorem 5's side of --conservatism: the value where it stops concluding, and the witness why
    scene = cli_scenes / "conservatism_coupling_witness_wall.toml"
    r = hapstab.stability(scene=scene, max="kap", conservatism=True)
    code, j = cli("stability", "--scene", str(scene), "--max", "kap", "--conservatism")
    na = r.theorem5["not_at"]
    assert na["theorem4_witness"] == j["theorem5"]["not_at"]["theorem4_witness"] and na["status"] == "exact"
    assert all(Fraction(x) <= 0 for x in na["theorem4_witness"]["phi"]) and "two-frequency witness" in na["why"]
    assert "theorem4_witness" not in r.theorem5["concludes_at"]  # as the command: only not_at is proven by one
    # a loop Theorem 4 was not proven infeasible for prints none
    c = hapstab.multidof.analyze(EXAMPLES / "multidof_case_ii_nominal.toml")
    assert c.loop_as_written["theorem4_witness"] is None and c.witness is None


def test_multidof_scene_text_names_no_temporary_file():
    text = (EXAMPLES / "multidof_case_i_nominal.toml").read_text().replace("[multidof]", "[multidof]\nops = 1", 1)
    with pytest.raises(hapstab.InputError) as e:
        hapstab.multidof.analyze(text)
    assert "/tmp" not in str(e.value) and "hapstab-scene" not in str(e.value), str(e.value)


# ---- simulate: numpy arrays ----------------------------------------------------------------

def test_simulate_returns_numpy_arrays_identical_to_the_csv(tmp_path):
    scene = EXAMPLES / "002_bias_wall.toml"
    s = hapstab.simulate(scene)
    code, j = cli("simulate", "--scene", str(scene), "--out", str(tmp_path / "cli"), "--quiet")
    for k in ("diverged", "max_velocity", "energy_generated", "trend", "steps_run", "limit_cycle"):
        assert s.summary[k] == j[k], k
    assert s.diverged is False and bool(s) and s.value == j["max_velocity"] and s.status == "numeric"
    rows = s.samples["t"].shape[0]
    assert rows > 1000 and s.samples["t"].dtype == np.float64
    for q in ("x", "v", "u", "fh", "E_port", "E_act", "E_po", "storage"):
        assert s.samples[q].shape == (rows, 1) and s.samples[q].dtype == np.float64, q
    assert s.units == {"t": "s", "x": "m", "v": "m/s", "u": "N", "fh": "N", "E_port": "J", "E_act": "J",
                       "E_po": "J", "storage": "J"}
    csv = np.loadtxt(tmp_path / "cli" / "samples.csv", delimiter=",", skiprows=1)
    assert np.array_equal(csv[:, 0], s.samples["t"]) and np.array_equal(csv[:, 2], s.samples["v"][:, 0])
    assert set(s.fine) == {"t", "x", "v"} and s.fine["x"].shape == (s.fine["t"].shape[0], 1)


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
    assert s.samples["v"].shape == (201, 2)
    stiff = hapstab.simulate(text, K=Fraction(400))
    assert not np.array_equal(stiff.samples["x"], s.samples["x"])
    assert s.fine is None and "samples='201x2'" in repr(s)
    with pytest.raises(hapstab.InputError, match="^scene:") as e:  # text scenes are called 'scene'
        hapstab.simulate(text.replace("[simulate]", "[simulat]"))
    assert "/tmp" not in str(e.value)
    with pytest.raises(hapstab.InputError, match="max_output=1e-06 MB; .*force=True"):
        hapstab.simulate(text, max_output=1e-6)


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

LONG_CALLS = {
    "simulate": f"hapstab.simulate({LONG_SCENE!r})",
    "bound_many": "hapstab.bound('K + B*(z-1)/(T*z)', T='1/1000', delay=1, params={'K': np.linspace(0, 4e4, 10**6), 'B': 5})",
    "multidof": "hapstab.multidof.design(hapstab.examples_dir() + '/multidof_case_ii_perturbed.toml', iterations=10000, "
                "duration=1e5)",
}


@pytest.mark.parametrize("what,to_group", [("simulate", False), ("bound_many", False), ("multidof", False),
                                           ("simulate", True), ("multidof", True)])
def test_ctrl_c_stops_a_long_call(what, to_group):
    # SIGINT while the call computes (a minute or more of work) must end it with KeyboardInterrupt
    # and leave the module usable; to_group: as a terminal's Ctrl-C does, to the process group
    code = (f"import numpy as np, hapstab\nprint('started', flush=True)\ntry:\n    {LONG_CALLS[what]}\n"
            "    print('completed')\nexcept KeyboardInterrupt:\n    print('interrupted', flush=True)\n"
            "    print(hapstab.bound('1', T=1).value)\n")
    p = subprocess.Popen([sys.executable, "-c", code], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                         start_new_session=True)
    assert p.stdout.readline().strip() == "started"
    time.sleep(1.0)  # inside the call by now (the import printed 'started' right before it)
    sent = time.monotonic()
    if to_group:
        os.killpg(p.pid, signal.SIGINT)
    else:
        p.send_signal(signal.SIGINT)
    out, err = p.communicate(timeout=120)  # a hang guard, not a measurement
    assert out.split() == ["interrupted", "1/2"], (out, err)
    assert p.returncode == 0, err
    assert time.monotonic() - sent < 60


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
        hapstab.bound(WALL, T="1/1000", delay=1, params={"K": np.linspace(0, 4e4, 3000), "B": 5})
        during = len(ticks) - before
    finally:
        stop.set()
        t.join()
    assert during > 0  # the ticker ran during the call: the GIL was free


def test_run_is_the_escape_hatch():
    code, j = hapstab.run("bound", "--H", WALL, "--T", "1/1000", "--set", "K=1000", "--set", "B=5", "--json")
    assert j["bound"] == "5.5" and code == 0


# ---- README: the Python section's code, and the install block on another python3 ---------------

SOURCE = Path(__file__).resolve().parents[2]


def _readme_block(language):
    return block("README.md", "Python", language)


def _docs_python_block():
    """docs/python.md's tour of the package (the README shows ten lines of it)."""
    return block("docs/python.md", None, "python")


def test_readme_python_block_runs_as_shown(monkeypatch):
    monkeypatch.chdir(SOURCE)  # its paths (examples/...) are relative to the top of the tree
    namespace = {}
    exec(compile(_readme_block("python"), "README.md (Python)", "exec"), namespace)
    b, bs, m = namespace["b"], namespace["bs"], namespace["m"]
    assert (b.value, b.status, b < 6) == (Fraction(221, 40), "exact", True)  # as its comment says
    assert bs.shape == (10001,) and m.lo_exact.startswith("1236.0679") and m.closed_form["equation"] == "(53)"


def test_docs_python_block_runs_as_shown(monkeypatch):
    monkeypatch.chdir(SOURCE)
    namespace = {}
    exec(compile(_docs_python_block(), "docs/python.md", "exec"), namespace)
    assert namespace["b"].status in ("exact", "certified") and namespace["bs"].shape == (10001,)
    assert namespace["t"]["bound"].dtype == np.float64 and len(namespace["t"]) == 123


def test_readme_install_block_names_the_interpreter():
    block = _readme_block("sh")
    assert block.startswith("/usr/bin/python3 -m venv --system-site-packages venv")
    assert "HAPSTAB_BUILD_DIR=build venv/bin/pip install --no-build-isolation --no-index ." in block


def test_readme_shows_the_kernel_line_the_notebook_test_runs():
    # issue 49: Debian's kernel runs /usr/bin/python3, which does not see README's venv; the line that
    # registers the venv as a kernel is docs/python.md's Jupyter block, which ctest python_notebook
    # runs (tests/python/run_notebook.py); README shows the same line
    line = block("docs/python.md", "Jupyter", "sh").strip()
    assert line.startswith("venv/bin/python -m ipykernel install --user --name ") and "\n" not in line
    assert f"`{line}`" in (SOURCE / "README.md").read_text(encoding="utf-8")


def test_readme_pip_block_on_a_fresh_clone_says_what_to_run(tmp_path):
    # issue 49: README's block copied before any build (HAPSTAB_BUILD_DIR=build, no build folder)
    # stops at once with one line that says what to run, not a traceback from inside setuptools
    missing = tmp_path / "build"
    p = subprocess.run(["/usr/bin/python3", "setup.py", "--name"], cwd=SOURCE, capture_output=True, text=True,
                       env=dict(os.environ, HAPSTAB_BUILD_DIR=str(missing)), check=False)
    assert p.returncode != 0 and "Traceback" not in p.stderr, p.stderr
    assert p.stderr.strip().splitlines() == [
        f"hapstab: HAPSTAB_BUILD_DIR={missing}: {missing} is not a configured CMake build folder yet: run "
        f"`cmake -S . -B {missing} -DCMAKE_BUILD_TYPE=Release` first (pip then builds the module there, minutes the "
        "first time), or leave HAPSTAB_BUILD_DIR out"], p.stderr


def test_setup_py_names_a_python_that_cannot_build_offline():
    # the case README names: a python3 first on PATH that is not Debian's (this machine's pyenv)
    import shutil
    other = shutil.which("python3")
    if other is None or os.path.realpath(other) == os.path.realpath("/usr/bin/python3"):
        pytest.skip("the first python3 on PATH is Debian's")
    probe = subprocess.run([other, "-c", "import wheel, numpy"], capture_output=True, check=False)
    if probe.returncode == 0:
        pytest.skip(f"{other} has wheel and numpy: it can build")
    p = subprocess.run([other, "setup.py", "bdist_wheel"], cwd=SOURCE, capture_output=True, text=True, check=False)
    assert p.returncode != 0
    assert "hapstab: this Python (" in p.stderr and "/usr/bin/python3 -m venv" in p.stderr, p.stderr
    assert "invalid command 'bdist_wheel'" not in p.stderr


def test_array_comparisons_decide_exact_values_exactly():
    # b* = 1/2 + K/2000 exactly: at K = 1000 - 2^-50 it is just below 1 but not a double, so its
    # float ends straddle 1; the comparison uses the exact value (kb_map.py met this case)
    K = np.array([Fraction(1000) - Fraction(1, 2**50), 1000, Fraction(1000) + Fraction(1, 2**50)], dtype=object)
    bs = hapstab.bound(WALL, T="1/1000", params={"K": K, "B": "1/2"})
    assert list(bs.status) == ["exact"] * 3 and bs.lo[0] < 1 <= bs.hi[0]
    assert list(bs < 1) == [True, False, False] and list(bs <= 1) == [True, True, False]
    assert list(bs > 1) == [False, False, True] and list(bs >= 1) == [False, True, True]


def test_multidof_symmetry_is_the_commands():
    # issue 48: (16) split by the permutations of identical DOFs; the blocks come back as
    # `multidof analyze --json` prints them
    cli_scenes = Path(__file__).resolve().parents[1] / "cli" / "scenes"
    a = hapstab.multidof.analyze(cli_scenes / "symmetric_contact_6.toml")
    code, j = cli("multidof", "analyze", "--scene", str(cli_scenes / "symmetric_contact_6.toml"))
    assert a.path == j["path"] == "symmetry" and a.feasible and a.certified
    s = a.symmetry
    assert s["group"] == j["symmetry"]["group"] and s["classes"] == j["symmetry"]["classes"] == [[0, 4], [1, 5], [2], [3]]
    assert [b["verdict"] for b in s["blocks"]] == ["feasible"] * 3
    w = hapstab.multidof.analyze(cli_scenes / "witness_interior_wall.toml")
    assert w.symmetry is None


def test_set_aside_modes_that_chain_are_undecided_in_python_too():
    # stop 87's review: an environment hiding a constant force beside a sum of positions (both at z = 1) makes
    # z = 1 a Jordan block of the loop as written; the command says undecided (Edges.SetAsideModesThatChainAreUndecided),
    # and so does Python, for the verdict and for max= (no supremum is stated)
    scene = SCENES / "hidden_offset_and_integrator.toml"
    s = hapstab.stability(scene=scene)
    assert s.stable is None and s.verdict_status == "undecided"
    r = hapstab.stability(scene=scene, max="g")
    assert r.status == "undecided" and r.outcome == "undecided" and r.path == "hidden_modes" and not r.supremum_proven
    assert math.isnan(r.value) and "Jordan block at z = 1" in r.note
