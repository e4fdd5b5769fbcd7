"""sl.check: the kit on scatterlab materials and on BSDFs written in numpy. A correct numpy lobe
passes; one whose pdf exponent is 10% off, a mirror that misstates its probability and a
lossless claim 0.1% short are rejected; the negative controls wrapped around a Python object are
rejected; the Python-object path reproduces a material's own report exactly, on any number of
threads."""

import json

import numpy as np
import pytest

import scatterlab as sl
from numpy_bsdfs import DiffuseTransmitter, MaterialAsObject, Mirror, PhongLobe, WhiteLambertian

# Small enough for CI, large enough that the 10%-off exponent is rejected at every angle: a 10%
# change of a Phong exponent of 20 moves about 2% of the samples between cells, a chi-square
# excess of many hundred at 2 * 10^5 samples against a Sidak threshold near 60 over 2047 dof.
# Each incident angle of a Python object costs about ten seconds on two cores (the replay,
# docs/python.md, "The kit on any object"), so the tests use one or two angles: normal and oblique.
SAMPLES = 2 * 10**5
ANGLES = (0, 60)


def rows(report, test):
    return [r for r in report.rows if r["test"] == test]


def test_numpy_phong_lobe_passes_every_check():
    report = sl.check(PhongLobe(exponent=20), wi_theta=ANGLES, samples=SAMPLES, progress=False)
    assert report.passed, str(report)
    assert len(rows(report, "chi2")) == len(ANGLES)
    assert {r["test"] for r in report.rows} >= {"chi2", "consistency", "normalisation", "albedo", "reciprocity"}


def test_phong_lobe_with_pdf_exponent_ten_percent_off_is_rejected_by_the_chi_square():
    report = sl.check(PhongLobe(exponent=20, pdf_exponent=22), wi_theta=ANGLES, samples=SAMPLES, progress=False)
    assert not report.passed
    chi2 = rows(report, "chi2")
    assert chi2 and not any(r["passed"] for r in chi2), str(report)
    # Its per-sample identities hold: the histogram alone sees the error.
    assert all(r["passed"] for r in rows(report, "consistency")), str(report)


def test_negative_controls_wrapped_around_a_python_object_are_rejected():
    report = sl.check(PhongLobe(exponent=20), wi_theta=(30,), samples=SAMPLES, negative_controls=True,
                      progress=False)
    controls = {r["test"]: r for r in report.rows if r["test"].startswith("control: ")}
    # The two controls that wrap any model apply to the lobe and are rejected (a control's row
    # passes when the kit rejected it). The lobe's pdf is symmetric in wi and wo, so the swap
    # control says it is not applicable; a Python object has no lobe width to change.
    for name in ("control: pdf +5% on half the sphere", "control: missing half-vector Jacobian"):
        assert controls[name]["note"] == "rejected" and controls[name]["passed"], str(report)
    assert controls["control: wi/wo swapped in pdf"]["note"].startswith("not applicable"), str(report)
    assert controls["control: sampler lobe width 10% off"]["note"].startswith("not applicable"), str(report)
    assert report.passed, str(report)


def test_python_object_path_reproduces_the_materials_own_report_exactly():
    m = sl.material({"type": "conductor", "alpha": 0.2})
    direct = sl.check(m, wi_theta=(60,), samples=20000, label="gold", progress=False)
    replayed = sl.check(MaterialAsObject(m), wi_theta=(60,), samples=20000, label="gold", progress=False)
    assert replayed.rows == direct.rows


def test_same_report_on_one_and_on_two_threads():
    one = sl.check(WhiteLambertian(0.8), wi_theta=(45,), samples=20000, threads=1, progress=False)
    two = sl.check(WhiteLambertian(0.8), wi_theta=(45,), samples=20000, threads=2, progress=False)
    assert one.rows == two.rows


def test_lossless_white_lambertian_passes_the_furnace():
    report = sl.check(WhiteLambertian(1.0), wi_theta=(60,), samples=20000, progress=False)
    assert report.passed, str(report)
    assert len(rows(report, "furnace")) == 1


def test_lossless_claim_a_thousandth_short_fails_the_furnace():
    report = sl.check(WhiteLambertian(0.999), wi_theta=(60,), samples=20000, progress=False)
    furnace = rows(report, "furnace")
    assert furnace and not any(r["passed"] for r in furnace), str(report)


def test_delta_mirror_passes_and_one_misstating_its_probability_is_rejected():
    good = sl.check(Mirror(probability=0.7), wi_theta=(45,), samples=20000, progress=False)
    assert good.passed, str(good)
    broken = sl.check(Mirror(probability=0.7, claimed=0.75), wi_theta=(45,), samples=20000, progress=False)
    assert not any(r["passed"] for r in rows(broken, "chi2")), str(broken)


def test_transmitter_declaring_transmission_is_checked_from_above_and_below():
    report = sl.check(DiffuseTransmitter(), wi_theta=(60,), samples=20000, progress=False)
    assert report.passed, str(report)
    # 60 degrees and its mirror image below the surface, 120.
    assert sorted(r["wi_theta"] for r in rows(report, "chi2")) == [60, 120]


def test_material_check_rows_are_the_executables_rows(run_json):
    material = {"type": "rough-plastic"}
    printed = run_json("check", json.dumps(material), "--samples", "20000", "--wi-theta", "0,45", "--seed", "3")
    report = sl.check(sl.material(material), wi_theta=(0, 45), samples=20000, seed=3, progress=False)
    assert json.loads(report.to_json())["rows"] == printed["report"]["rows"]


def test_report_rows_have_the_documented_keys():
    report = sl.check(sl.material({"type": "lambertian"}), wi_theta=(30,), samples=5000, progress=False)
    assert set(report.rows[0]) == {"material", "test", "wi_theta", "statistic", "dof", "p_value", "threshold",
                                   "passed", "note"}
    assert json.loads(report.to_json())["passed"] == report.passed
    assert "verdict: PASS" in str(report)


def test_object_without_sample_is_a_type_error():
    class NoSample:
        def eval(self, wi, wo):
            return np.zeros(len(wi))

        def pdf(self, wi, wo):
            return np.zeros(len(wi))

    with pytest.raises(TypeError, match="no method sample"):
        sl.check(NoSample(), samples=5000, progress=False)


def test_wrong_result_shape_is_refused_naming_the_method():
    class BadPdf(PhongLobe):
        def pdf(self, wi, wo):
            return np.zeros((len(wi), 2))

    with pytest.raises(ValueError, match=r"pdf\(wi, wo\) returned shape \(\d+, 2\)"):
        sl.check(BadPdf(), wi_theta=(30,), samples=5000, progress=False)


def test_declared_attribute_of_the_wrong_kind_is_refused():
    lobe = PhongLobe()
    lobe.lossless = "yes"
    with pytest.raises(ValueError, match="lossless.*True or False"):
        sl.check(lobe, samples=5000, progress=False)


@pytest.mark.parametrize("arguments, fragment", [
    ({"wi_theta": (90,)}, "wi_theta"),
    ({"wi_phi": 400}, "wi_phi"),
    ({"samples": 10}, "samples"),
    ({"grid": (1, 8)}, "grid"),
    ({"alpha": 1.5}, "alpha"),
    ({"threads": -1}, "threads"),
])
def test_bad_options_are_refused_naming_them(arguments, fragment):
    with pytest.raises(ValueError, match=fragment):
        sl.check(sl.material({"type": "lambertian"}), progress=False, **arguments)
