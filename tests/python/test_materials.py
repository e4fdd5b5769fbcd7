"""sl.material, sl.models and a Material's eval, pdf and sample on numpy arrays: the executable's
own numbers bit for bit, for every registry model; bad arguments raise ValueError naming them."""

import json
import pathlib

import numpy as np
import pytest

import scatterlab as sl


def bsdf_examples(data_dir):
    """One material of every BSDF model of the registry: its defaults, or for the measured model
    one of the shipped RGL files (its only parameter without a default is the file)."""
    examples = []
    for model in sl.models():
        if model["kind"] != "bsdf":
            continue
        if model["type"] == "measured":
            files = sorted((data_dir / "rgl").glob("*.bsdf"))
            assert files, "data/rgl holds no .bsdf file"
            examples.append({"type": "measured", "file": str(files[0])})
        else:
            examples.append({"type": model["type"]})
    return examples


def random_directions(rng, n, lower_half=False):
    w = rng.normal(size=(n, 3))
    w /= np.linalg.norm(w, axis=1)[:, None]
    if not lower_half:
        w[:, 2] = np.abs(w[:, 2])
    return w


def test_models_is_the_catalogue_the_executable_prints(run_json):
    assert sl.models() == run_json("models")


def test_every_bsdf_model_evaluates_as_the_executable_bit_for_bit(data_dir, scratch, run_json):
    rng = np.random.default_rng(7)
    wi = random_directions(rng, 24)
    wo = random_directions(rng, 24, lower_half=True)  # transmission too
    pairs = [{"wi": list(a), "wo": list(b)} for a, b in zip(wi, wo)]
    (scratch / "pairs.json").write_text(json.dumps(pairs))
    for example in bsdf_examples(data_dir):
        printed = run_json("eval", json.dumps(example), "--directions", str(scratch / "pairs.json"))["values"]
        # The executable normalises what it reads: evaluate at the directions it reports.
        wi_used = np.array([v["wi"] for v in printed])
        wo_used = np.array([v["wo"] for v in printed])
        m = sl.material(example)
        np.testing.assert_array_equal(m.eval(wi_used, wo_used), np.array([v["f"] for v in printed]), str(example))
        np.testing.assert_array_equal(m.pdf(wi_used, wo_used), np.array([v["pdf"] for v in printed]), str(example))


def test_every_bsdf_model_samples_as_the_executable_bit_for_bit(data_dir, scratch, run_json):
    rng = np.random.default_rng(11)
    wi = random_directions(rng, 24)
    u = rng.random(size=(24, 3))
    queries = [{"wi": list(w), "u_lobe": r[0], "u": [r[1], r[2]]} for w, r in zip(wi, u)]
    (scratch / "samples.json").write_text(json.dumps(queries))
    for example in bsdf_examples(data_dir):
        printed = run_json("eval", json.dumps(example), "--samples", str(scratch / "samples.json"))["samples"]
        wi_used = np.array([s["wi"] for s in printed])
        m = sl.material(example)
        wo, weight, pdf, valid, delta = m.sample(wi_used, u[:, 0], u[:, 1:], return_delta=True)
        np.testing.assert_array_equal(valid, [s["valid"] for s in printed], str(example))
        np.testing.assert_array_equal(wo, np.array([s["wo"] for s in printed]), str(example))
        np.testing.assert_array_equal(weight, np.array([s["weight"] for s in printed]), str(example))
        np.testing.assert_array_equal(pdf, np.array([s["pdf"] for s in printed]), str(example))
        np.testing.assert_array_equal(delta, [s["delta"] for s in printed], str(example))


def test_lambertian_is_albedo_over_pi_with_cosine_pdf():
    m = sl.material({"type": "lambertian", "albedo": [0.2, 0.4, 0.6]})
    wi = np.array([[0.0, 0.0, 1.0]])
    wo = np.array([[0.6, 0.0, 0.8]])
    # Closed forms in double: rounding only.
    np.testing.assert_allclose(m.eval(wi, wo), [[0.2 / np.pi, 0.4 / np.pi, 0.6 / np.pi]], rtol=1e-15)
    np.testing.assert_allclose(m.pdf(wi, wo), [0.8 / np.pi], rtol=1e-15)


def test_one_incident_direction_broadcasts_over_many_outgoing():
    m = sl.material({"type": "conductor", "alpha": 0.3})
    wo = random_directions(np.random.default_rng(3), 50)
    wi = np.array([0.0, 0.6, 0.8])
    np.testing.assert_array_equal(m.eval(wi, wo), m.eval(np.tile(wi, (50, 1)), wo))


def test_material_from_a_json_string_and_from_a_file_equals_the_dict(data_dir):
    spec = json.loads((data_dir / "materials" / "gold-anisotropic-ggx.json").read_text())
    a = sl.material(spec)
    b = sl.material(json.dumps(spec))
    c = sl.material(data_dir / "materials" / "gold-anisotropic-ggx.json")
    assert a.description == b.description == c.description
    assert c.label.endswith("gold-anisotropic-ggx.json")
    assert a.type == "conductor"


def test_description_is_completed_with_defaults():
    description = sl.material({"type": "conductor"}).description
    assert description["type"] == "conductor" and "alpha" in description


def test_a_measured_table_is_read_by_its_content(data_dir):
    path = sorted((data_dir / "rgl").glob("*.bsdf"))[0]
    assert sl.material(str(path)).type == "measured"


def test_unknown_key_is_refused_naming_it():
    with pytest.raises(ValueError, match="colour"):
        sl.material({"type": "lambertian", "colour": 1})


def test_value_out_of_range_is_refused_naming_the_key_and_the_range():
    with pytest.raises(ValueError, match="alpha") as error:
        sl.material({"type": "conductor", "alpha": -1})
    assert "allowed" in str(error.value) or "range" in str(error.value)


def test_nan_in_a_description_is_refused_naming_the_key():
    with pytest.raises(ValueError, match=r"materials\[1\]\.alpha"):
        sl.material({"type": "blend", "materials": [{"type": "lambertian"}, {"type": "conductor", "alpha": float("nan")}]})


def test_a_value_of_another_type_is_refused_naming_the_key():
    with pytest.raises(ValueError, match="albedo.*set"):
        sl.material({"type": "lambertian", "albedo": {0.5}})


def test_a_missing_file_is_refused_naming_it(scratch):
    with pytest.raises(ValueError, match="nothing-here.json"):
        sl.material(str(scratch / "nothing-here.json"))


def test_wrong_argument_type_is_a_type_error():
    with pytest.raises(TypeError, match="dict, a JSON string or the path"):
        sl.material(42)


def test_subsurface_material_has_no_eval():
    m = sl.material({"type": "subsurface"})
    assert m.is_subsurface
    with pytest.raises(ValueError, match="subsurface material.*sl.profile"):
        m.eval(np.array([[0.0, 0.0, 1.0]]), np.array([[0.0, 0.0, 1.0]]))


@pytest.mark.parametrize("wi, fragment", [
    (np.zeros((4, 2)), r"wi: expected shape \(N, 3\) or \(3,\), got \(4, 2\)"),
    (np.zeros((4, 3, 1)), r"wi: expected shape"),
    (np.array([[0.0, 0.0, 1.0]], dtype=np.float32), "wi: expected a float64 array.*float32"),
    (np.array([[0.0, 0.0, np.nan]] * 4), r"wi\[0\] = .* is not finite"),
    (np.array([[0.0, 0.0, 2.0]] * 4), r"wi\[0\] = .* has length 2.*unit vectors"),
    (np.array([["a", "b", "c"]] * 4), "wi: expected a float64 array"),
])
def test_bad_directions_are_refused_naming_the_argument(wi, fragment):
    m = sl.material({"type": "lambertian"})
    wo = np.tile([0.0, 0.0, 1.0], (4, 1))
    with pytest.raises(ValueError, match=fragment):
        m.eval(wi, wo)


def test_row_counts_that_disagree_are_refused():
    m = sl.material({"type": "lambertian"})
    with pytest.raises(ValueError, match="wo has 3 rows but wi has 4"):
        m.pdf(np.tile([0.0, 0.0, 1.0], (4, 1)), np.tile([0.0, 0.0, 1.0], (3, 1)))


@pytest.mark.parametrize("u_lobe, u, fragment", [
    (np.full(4, 1.0), np.zeros((4, 2)), r"u_lobe\[0\] = 1: random numbers must lie in \[0, 1\)"),
    (np.zeros(4), np.full((4, 2), -0.5), r"u\[0\] = \(-0.5, -0.5\)"),
    (np.zeros(4), np.zeros((4, 3)), r"u: expected shape \(N, 2\)"),
    (np.zeros(4), np.full((4, 2), np.nan), r"u\[0\]"),
])
def test_bad_random_numbers_are_refused_naming_the_argument(u_lobe, u, fragment):
    m = sl.material({"type": "lambertian"})
    with pytest.raises(ValueError, match=fragment):
        m.sample(np.tile([0.0, 0.0, 1.0], (4, 1)), u_lobe, u)


def test_unknown_transport_mode_is_refused():
    m = sl.material({"type": "dielectric"})
    with pytest.raises(ValueError, match="mode.*radiance.*importance"):
        m.eval(np.array([0.0, 0.0, 1.0]), np.array([0.0, 0.0, -1.0]), mode="adjoint")


def test_failed_samples_are_zero_and_invalid_never_nan():
    m = sl.material({"type": "lambertian"})
    wo, weight, pdf, valid = m.sample(np.array([0.0, 0.0, -1.0]), np.zeros(8), np.full((8, 2), 0.5))
    assert not valid.any()
    assert np.all(wo == 0) and np.all(weight == 0) and np.all(pdf == 0)


def test_a_million_evaluations_return_finite_values():
    m = sl.material({"type": "conductor", "alpha": 0.2})
    rng = np.random.default_rng(5)
    f = m.eval(random_directions(rng, 10**6), random_directions(rng, 10**6))
    assert f.shape == (10**6, 3) and np.isfinite(f).all()
