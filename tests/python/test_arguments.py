"""One rule for the arguments of the package (contensou/_args.py): a number is an int, a float or
a numpy scalar, never a str or a bool, in every function and constructor that takes one; a
profile is a PressureProfile or a built-in profile's name wherever one is taken; a wrong type is
a short TypeError naming the argument and what it accepts (not nanobind's signature dump). And
the other edges of the bindings: NaN in a gear configuration, the shimmy app's model aliases, a
1-D stability map, subnormal scales of a law."""

from __future__ import annotations

import math

import numpy as np
import pytest

import contensou as c
from contensou import _args, gear

from conftest import DATA

SHORT = 200  # characters: a TypeError of one line, not a signature listing


def short_type_error(call, *pattern: str) -> str:
    with pytest.raises(TypeError) as e:
        call()
    text = str(e.value)
    assert len(text) < SHORT and "incompatible function arguments" not in text, text
    for p in pattern:
        assert p in text, text
    return text


def test_the_number_rule():
    for ok in (1, 0.5, np.float32(0.25), np.int64(3), np.array(2.5), np.float64("nan")):
        assert isinstance(_args.number("x", ok), float)
    for bad in ("0.087", b"1", True, np.bool_(False), None, [1.0], np.array([1.0, 2.0]), 1j):
        short_type_error(lambda: _args.number("radius", bad), "radius: a number is required, not")
    assert _args.integer("n", 3.0) == 3
    with pytest.raises(ValueError, match=r"^n = 2.5: must be a whole number$"):
        _args.integer("n", 2.5)


def patch(**kw):
    args = dict(radius_m=0.087, normal_load=4500.0, friction=0.3)
    args.update(kw)
    return c.ContactPatch(**args)


@pytest.mark.parametrize("name", ["uniform", "hertz", "seed-tire"])
def test_a_built_in_profiles_name_is_a_profile_wherever_one_is_taken(name):
    """ContactPatch(profile=...) and from_normal_load take the names identify(profile=...) and
    the apps take, for the same profile as the factory's; so does shape_values."""
    factory = {"uniform": c.uniform_profile, "hertz": c.hertz_profile,
               "seed-tire": c.seed_tire_profile}[name]
    by_name, by_object = patch(profile=name), patch(profile=factory())
    assert by_name.reference_pressure_pa == by_object.reference_pressure_pa
    assert by_name.profile.describe() == factory().describe()
    loaded = c.ContactPatch.from_normal_load(0.087, 4500.0, name, 0.3)
    assert loaded.reference_pressure_pa == by_object.reference_pressure_pa
    rho = np.linspace(0, 1, 7)
    np.testing.assert_array_equal(c.shape_values(name, rho), c.shape_values(factory(), rho))


def test_constructors_refuse_a_wrong_type_with_a_short_type_error():
    short_type_error(lambda: patch(radius_m="0.087"), "radius_m: a number is required, not str "
                                                      "'0.087'")
    short_type_error(lambda: patch(normal_load=True), "normal_load: a number is required, not bool")
    short_type_error(lambda: patch(kappa="1"), "kappa: a number")
    short_type_error(lambda: patch(profile=3), "profile: a PressureProfile or a built-in "
                                               "profile's name (uniform, hertz, seed-tire)")
    short_type_error(lambda: patch(slip_speed_friction=0.3), "slip_speed_friction: a "
                                                             "SlipSpeedFriction or None")
    with pytest.raises(ValueError, match=r"^profile = 'cone': a built-in profile is one of "
                                         r"uniform, hertz, seed-tire"):
        patch(profile="cone")
    short_type_error(lambda: c.ContactPatch.from_normal_load("0.087", 4500.0, "hertz", 0.3),
                     "radius_m: a number")
    short_type_error(lambda: c.SlipSpeedFriction("0.8"), "static_coefficient: a number")
    short_type_error(lambda: c.FractionalLaw(F0="1375"), "F0: a number is required, not str")
    short_type_error(lambda: c.FractionalLaw(1.0, 2.0, "1"), "a: a number")
    short_type_error(lambda: c.ExactModel("patch"), "patch: a ContactPatch is required, not str")
    short_type_error(lambda: c.ExactModel(patch(), representation_tolerance="1e-15"),
                     "representation_tolerance: a number")
    short_type_error(lambda: c.LimitSurface(c.seed_tire_profile()), "patch: a ContactPatch")
    short_type_error(lambda: c.EllipsoidalLimitSurface("1", 0.03, 0.1), "force_limit: a number")
    short_type_error(lambda: c.ExactLaw(patch(), tolerance="small"), "tolerance: a number is "
                                                                      "required, not str 'small'")
    # numpy scalars are numbers: the same patch as from floats.
    assert (patch(radius_m=np.float32(0.25)).radius_m == 0.25
            and patch(normal_load=np.int64(4500)).reference_pressure_pa
            == patch().reference_pressure_pa)


def test_functions_refuse_a_string_for_a_number_too():
    short_type_error(lambda: c.cosine_series_profile("0.848", [1.0]), "w: a number")
    short_type_error(lambda: c.cosine_series_profile(0.848, "1,2"), "a: a sequence of numbers")
    short_type_error(lambda: c.tabulated_profile("0,1", [1, 1]), "rho: a sequence of numbers")
    short_type_error(lambda: c.tabulated_profile([0, "1"], [1, 1]), "rho[1]: a number")
    short_type_error(lambda: c.smoothed_profile([0, 0.5, 1], [1, 1, 1], "2"), "terms: a number")
    short_type_error(lambda: c.hertz_profile().moment("1"), "n: a number")
    short_type_error(lambda: c.fractional_law_from_patch("hertz"), "patch: a ContactPatch")
    short_type_error(lambda: c.fractional_law_fitted(patch(), "0.01"), "psi_min: a number")
    # Sequences of numbers: lists, tuples, numpy arrays and pandas Series alike.
    pd = pytest.importorskip("pandas")
    for rho in ([0, 0.5, 1], (0, 0.5, 1), np.array([0, 0.5, 1]), pd.Series([0, 0.5, 1])):
        table = c.tabulated_profile(rho, [1.0, 0.8, 0.2])
        assert table.moment(1) == c.tabulated_profile([0, 0.5, 1], [1.0, 0.8, 0.2]).moment(1)
    # A patch's profile is set from a name too.
    p = patch()
    p.profile = "hertz"
    assert p.profile.describe() == "Hertz"
    p.profile.kx = 0.1  # the profile of the patch, not a copy
    assert p.profile.kx == 0.1
    short_type_error(lambda: setattr(p, "profile", 1), "profile: a PressureProfile")
    law = c.fractional_law_from_patch(patch())
    short_type_error(lambda: c.exact_resultants(patch(), 0.1, 0.0, 1.0, tolerance="1e-8"),
                     "tolerance: a number")
    short_type_error(lambda: c.exact_resultants(law, 0.1, 0.0, 1.0),
                     "model: an ExactModel or a ContactPatch is required, not FractionalLaw")
    from contensou.engines import engine_coefficients

    short_type_error(lambda: engine_coefficients("uniform", "0.1", 0.5), "--radius: a number")
    short_type_error(lambda: engine_coefficients(c.uniform_profile(), 0.1, 0.5),
                     "--profile: a built-in profile's name")
    short_type_error(lambda: c.identify(DATA, radius="0.087", loop=False),
                     "radius: a number is required, not str '0.087'")
    short_type_error(lambda: c.identify(DATA, radius=0.087, pressure="2.1e5"), "pressure: a number")
    short_type_error(lambda: c.identify(DATA, radius=0.087, fix={"a": "1"}), "fix['a']: a number")
    short_type_error(lambda: c.identify(DATA, radius=0.087, alpha=None), "alpha: a number")
    short_type_error(lambda: c.identify(DATA, radius=0.087, loop="no"), "loop: True or False")
    short_type_error(lambda: c.identify(DATA, radius=0.087, profile=c.hertz_profile()),
                     "profile: a built-in profile's name (uniform, hertz, seed-tire) or the path")
    with pytest.raises(ValueError, match="whole number"):
        c.identify(DATA, radius=0.087, profile_smoothing=2.5)
    short_type_error(lambda: c.stability_map(None, ("scenario.forward_speed_mps", "40", 80.0, 2)),
                     "axis scenario.forward_speed_mps: from: a number")


def test_a_subnormal_scale_of_the_law_is_refused_naming_it():
    """F0, M0 and Mk are 0 or normal doubles (as loads are): FractionalLaw refuses a subnormal one
    where it is made, and a law changed afterwards is refused when it is used."""
    with pytest.raises(ValueError, match=r"^F0 = 1e-310: is below 2.2e-308, the smallest normal"):
        c.FractionalLaw(F0=1e-310, M0=1.0)
    law = c.fractional_law_from_patch(patch())
    law.M0 = 5e-324
    with pytest.raises(ValueError, match=r"^M0 = 5e-324: is below 2.2e-308"):
        c.fractional_resultants(law, 0.1, 0.0, 1.0)
    law.M0 = 0.0  # zero is a value: no spin torque
    assert np.isfinite(c.fractional_resultants(law, 0.1, 0.0, 1.0)).all()
    with pytest.raises(ValueError, match=r"^friction = 1e-310: is below 2.2e-308"):
        patch(friction=1e-310)


def test_a_nan_in_a_gear_configuration_is_named():
    """JSON has no NaN: the field is named and NaN (or infinity) said to be not allowed, where
    the JSON reader said 'invalid JSON'; in the constructor, by item and by replace."""
    for build in (lambda: c.LandingConfig({"structure": {"offset_m": math.nan}}),
                  lambda: c.LandingConfig().replace(structure__offset_m=float("nan")),
                  lambda: c.LandingConfig().replace(scenario__forward_speed_mps=np.float64("inf"))):
        with pytest.raises(ValueError, match=r"^(structure\.offset_m = nan|scenario\.forward_speed"
                                             r"_mps = inf): NaN and infinities are not allowed"):
            build()
    cfg = c.LandingConfig()
    with pytest.raises(ValueError, match=r"^structure\.offset_m = nan: NaN"):
        cfg["structure.offset_m"] = float("nan")
    assert math.isfinite(cfg["structure.offset_m"])  # unchanged


def test_the_shimmy_apps_model_names_are_accepted():
    """The names contensou-shimmy takes (its aliases too) are the names Python takes; the result
    names the model as the app's reports do."""
    assert gear._model("nonholonomic") == "von_schlippe"
    for name in gear.MODELS:
        assert gear._model(name) == name
    with pytest.raises(ValueError, match=r"^model = 'vs': must be one of coupled, decoupled, "
                                         r"von_schlippe \(also nonholonomic for von_schlippe\)"):
        c.simulate_landing(None, "vs")
    short_type_error(lambda: c.simulate_landing(None, 3), "model: a model's name")


def test_a_stability_map_of_one_axis_is_a_1d_sweep():
    """One axis (alone, or in a sequence of one) is a sweep: one row, the same cells as the row
    of a 2-D map at the configuration's value of the other axis (y is then a 1-point axis of
    another parameter at its configured value, which changes nothing)."""
    cfg = c.LandingConfig().replace(structure__torsional_damping_nms_per_rad=100.0)
    sweep = ("scenario.forward_speed_mps", 40.0, 80.0, 2)
    one = c.stability_map_native(cfg, sweep, threads=2)
    assert one.growth_rate_per_s.shape == (1, 2) and one.y.points == 1
    assert cfg[one.y.parameter] == one.y.start
    grid = c.stability_map_native(
        cfg, (sweep, ("structure.torsional_damping_nms_per_rad", 100.0, 200.0, 2)), threads=2)
    np.testing.assert_array_equal(one.growth_rate_per_s[0], grid.growth_rate_per_s[0])
    np.testing.assert_array_equal(one.frequency_hz[0], grid.frequency_hz[0])
    also = c.stability_map_native(cfg, [sweep], threads=2)
    np.testing.assert_array_equal(also.growth_rate_per_s, one.growth_rate_per_s)
    with pytest.raises(ValueError, match="x and y are both scenario.forward_speed_mps"):
        c.stability_map_native(cfg, (sweep, sweep))
    with pytest.raises(ValueError, match="give \\(x, y\\)"):
        c.stability_map_native(cfg, (sweep, sweep, sweep))
