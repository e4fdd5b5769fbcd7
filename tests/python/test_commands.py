"""sl.fit, sl.render and sl.profile: the command line's work as functions. Each returns what the
command computes for the same options, exactly (same seed, same numbers); its keywords are the
command's options, so a bad one is refused with the command's message."""

import json
import subprocess

import numpy as np
import pytest

import scatterlab as sl

# lambertian 0.2 + Cook-Torrance (albedo 0.2, F0 0.3, roughness 0.1) as one registry material,
# and the small fit settings of the command line's own fit tests (tests/app/fit_cli_test.cpp).
TRUTH = {"type": "blend", "weight": 0.5, "materials": [
    {"type": "lambertian", "albedo": 0.4},
    {"type": "ngan-cook-torrance", "albedo": 0.4, "eta": 0.3, "roughness": 0.1}]}
QUICK = {"samples": 20000, "grid_points": 64, "starts": 2}
MODEL = "lambertian+ngan-cook-torrance"
SPHERE = {"type": "conductor", "alpha": 0.3}


def parameter(parameters, name):
    return next(p for p in parameters if p["name"] == name)


@pytest.fixture(scope="module")
def fitted():
    """One fit, shared by the tests that read its result."""
    return sl.fit(TRUTH, model=MODEL, metric="low-log", progress=False, **QUICK)


def test_fit_recovers_the_parameters_of_a_tabulated_material(fitted):
    result = fitted
    assert result.good, result.report["problems"]
    # Noise-free data from the model itself: recovered to the tolerance of the command's own test
    # (1e-5 on the roughness, tests/app/fit_cli_test.cpp, from the solver's convergence limits).
    assert abs(parameter(result.parameters, "ngan-cook-torrance.roughness")["value"] - 0.1) < 1e-5
    assert result.material["type"] == "blend"
    assert result.report["written"] is None


def test_fit_covariance_is_square_symmetric_and_matches_the_reported_standard_errors(fitted):
    result = fitted
    p = len(result.parameters)
    assert result.covariance.shape == (p, p)
    # Symmetric as correlations: Ceres inverts J^T J numerically, so its two triangles agree only
    # to rounding amplified by the condition number; 1e-6 in correlation is far above that for a
    # well-posed fit and far below a real fault (a transposed block differs by order 1).
    scale = np.sqrt(np.outer(np.diag(result.covariance), np.diag(result.covariance)))
    assert np.all(np.diag(result.covariance) > 0)
    assert np.all(np.abs(result.covariance - result.covariance.T) <= 1e-6 * scale)
    for i, entry in enumerate(result.parameters):
        if entry.get("std_dev") is not None:
            # The report's standard deviation is the square root of the diagonal (same doubles).
            assert np.sqrt(result.covariance[i, i]) == pytest.approx(entry["std_dev"], rel=1e-12)


def test_fit_values_and_errors_are_arrays_in_covariance_order(fitted):
    result = fitted
    assert result.values.shape == result.errors.shape == (len(result.names),)
    assert result.names == [p["name"] for p in result.parameters]
    assert result.values[result.names.index("ngan-cook-torrance.roughness")] == pytest.approx(0.1, abs=1e-5)


def test_fit_report_is_the_command_lines_json_report(scatterlab_exe):
    result = sl.fit(TRUTH, model=MODEL, metric="ngan", progress=False, **QUICK)
    run = subprocess.run([scatterlab_exe, "--quiet", "fit", json.dumps(TRUTH), "--model", MODEL, "--metric", "ngan",
                          "--samples", "20000", "--grid-points", "64", "--starts", "2", "--json"],
                         capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    command = json.loads(run.stdout)
    for timing in ("seconds",):
        command["fit"].pop(timing, None)
        result.report["fit"].pop(timing, None)
    assert result.report == command


def test_fit_refuses_an_unknown_keyword_and_names_the_allowed_ones():
    with pytest.raises(ValueError, match=r"sl\.fit: unknown keyword sampels; allowed: .*samples"):
        sl.fit(TRUTH, model=MODEL, metric="ngan", sampels=20000, progress=False)


def test_fit_refuses_out_because_the_result_is_returned():
    with pytest.raises(ValueError, match=r"sl\.fit: out: only shapes what the command line writes"):
        sl.fit(TRUTH, model=MODEL, metric="ngan", out="fit.json", progress=False)


def test_fit_refuses_a_value_out_of_range_with_the_command_lines_message():
    with pytest.raises(ValueError, match=r"sl\.fit: --samples: \"-5\" .*allowed: an integer >= 0"):
        sl.fit(TRUTH, model=MODEL, metric="ngan", samples=-5, progress=False)


def test_fit_refuses_an_unknown_model_naming_it():
    with pytest.raises(ValueError, match=r"--model.*no-such-model"):
        sl.fit(TRUTH, model="no-such-model", metric="ngan", progress=False, **QUICK)


def test_render_image_is_the_exr_the_command_line_writes(scatterlab_exe, scratch):
    image, report = sl.render(SPHERE, res="32x24", spp=4, seed=3, progress=False)
    assert image.shape == (24, 32, 3) and image.dtype == np.float32
    assert np.isfinite(image).all()
    prefix = scratch / "sphere"  # the command writes PREFIX.exr and PREFIX.png
    run = subprocess.run([scatterlab_exe, "--quiet", "render", json.dumps(SPHERE), "--res", "32x24", "--spp", "4",
                          "--seed", "3", "--out", str(prefix)], capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    assert np.array_equal(sl.read_exr(scratch / "sphere.exr"), image)  # both 32-bit float: the same numbers
    assert report["dropped_samples"] == 0


def test_render_takes_the_resolution_as_a_width_height_tuple():
    image, _ = sl.render(SPHERE, res=(20, 10), spp=1, progress=False)
    assert image.shape == (10, 20, 3)


def test_render_of_a_material_object_equals_the_render_of_its_description():
    m = sl.material(SPHERE)
    a, _ = sl.render(m, res="16x16", spp=2, progress=False)
    b, _ = sl.render(SPHERE, res="16x16", spp=2, progress=False)
    assert np.array_equal(a, b)


def test_render_is_the_same_on_one_and_on_two_threads():
    one, _ = sl.render(SPHERE, res="16x16", spp=4, threads=1, progress=False)
    two, _ = sl.render(SPHERE, res="16x16", spp=4, threads=2, progress=False)
    assert np.array_equal(one, two)


def test_render_refuses_a_bad_resolution_with_the_command_lines_message():
    with pytest.raises(ValueError, match=r"--res: \"0x5\" is not a valid resolution; allowed:"):
        sl.render(SPHERE, res="0x5", progress=False)


def test_render_refuses_exposure_which_only_shapes_the_png():
    with pytest.raises(ValueError, match=r"sl\.render: exposure: only shapes"):
        sl.render(SPHERE, exposure=1.0, progress=False)


def test_profile_is_the_command_lines_json_document(run_json):
    material = {"type": "subsurface", "profile": "dipole"}
    document = sl.profile(material, bins=8, progress=False)
    assert document == run_json("--quiet", "profile", json.dumps(material), "--bins", "8")
    assert len(document["channels"]) == 3
    assert len(document["radius_edges"]) == 9


def test_profile_with_a_walk_reference_is_reproducible_from_its_seed():
    material = {"type": "subsurface"}
    a = sl.profile(material, reference="walk", paths=20000, bins=6, seed=5, progress=False)
    b = sl.profile(material, reference="walk", paths=20000, bins=6, seed=5, progress=False)
    assert a == b
    assert all("walk" in channel for channel in a["channels"])


def test_profile_refuses_a_bsdf_naming_what_is_allowed():
    with pytest.raises(ValueError, match=r"subsurface"):
        sl.profile({"type": "lambertian"}, progress=False)
