"""scatterlab for Python: every material model on numpy arrays, the statistical test kit on any
BSDF (scatterlab's or one written in numpy), fits and renders as arrays.

    import scatterlab as sl
    m = sl.material({"type": "conductor", "alpha": 0.2})
    f = m.eval(wi, wo)                      # (N, 3) float64 directions in the local frame
    report = sl.check(m)                    # or sl.check(my_numpy_bsdf)

The API and its conventions are documented in docs/python.md; the C++ behind it is the same code
the `scatterlab` command line runs.
"""

from . import _scatterlab
from ._scatterlab import CheckReport, Material, __version__, load_plugin
from .commands import FitResult, fit, profile, read_exr, render

__all__ = ["CheckReport", "FitResult", "Material", "__version__", "check", "fit", "load_plugin", "material", "models", "profile",
           "read_exr", "render"]


def material(spec):
    """A registry material from a dict, a JSON string, or the path of a material file or a
    measured table (MERL .binary, RGL .bsdf), validated as `scatterlab check` validates it.
    Raises ValueError naming the key, value or file and what is allowed."""
    return _scatterlab._material(spec)


def models():
    """The catalogue of material models: what `scatterlab models --json` prints, as a list of
    dicts (type, description, citation, parameters with ranges and defaults)."""
    return _scatterlab._models()


def _sample(self, wi, u_lobe, u, mode="radiance", return_delta=False):
    """Samples wo for each wi: returns (wo, weight, pdf, valid), with is_delta appended when
    return_delta. wi (N, 3) or (3,), u_lobe (N,), u (N, 2), all float64, u in [0, 1).
    weight = f |cos wo| / pdf; a failed sample has valid False and zeros elsewhere; for a delta
    lobe pdf is the discrete probability of choosing it."""
    wo, weight, pdf, valid, delta = self._sample(wi, u_lobe, u, mode)
    return (wo, weight, pdf, valid, delta) if return_delta else (wo, weight, pdf, valid)


Material.sample = _sample


def check(bsdf, wi_theta=(0, 30, 60, 85), wi_phi=30.0, samples=10**6, seed=1, grid=(64, 128),
          negative_controls=False, alpha=0.01, label=None, progress=True, image_dir=None, threads=0):
    """Runs the test kit (docs/validation.md) on `bsdf` and returns a CheckReport.

    `bsdf` is a scatterlab Material, or any object with eval(wi, wo) -> (N, 3) or (N,),
    pdf(wi, wo) -> (N,) and sample(wi, u_lobe, u) -> (wo, weight, pdf, valid) on float64 numpy
    arrays, in the local frame (docs/python.md). Optional attributes: lossless (bool; the
    furnace row then checks albedo 1 within lossless_accuracy), delta (bool; sample then returns
    is_delta as a fifth array), reciprocal (bool, default True).

    wi_theta: incident polar angles in degrees; wi_phi: their azimuth; samples: per chi-square test; grid: (cos theta,
    phi) cells; alpha: family-wise significance (Sidak-corrected per test); negative_controls:
    also run deliberately broken variants of the model, whose rows pass when the kit rejects
    them. The same seed gives the same report whatever the number of threads (threads: the most
    cores to use, 0 for all). image_dir: also write the observed, expected and residual PNG maps
    of every chi-square test there. progress: one line per stage on stderr."""
    wi_theta = [float(t) for t in wi_theta]
    # The ranges of `scatterlab check`'s options (docs/validation.md).
    if not wi_theta or any(not (0.0 <= t < 90.0) for t in wi_theta):
        raise ValueError("wi_theta: incident polar angles in degrees, each in [0, 90) (a model with "
                         "transmission is also checked from below); got %r" % (wi_theta,))
    if not (-360.0 <= wi_phi <= 360.0):
        raise ValueError("wi_phi: the incident azimuth in degrees, in [-360, 360]; got %r" % (wi_phi,))
    if isinstance(samples, bool) or not isinstance(samples, int) or not (1000 <= samples <= 10**11):
        raise ValueError("samples: an integer in [1000, 10^11] per chi-square test; got %r" % (samples,))
    if isinstance(seed, bool) or not isinstance(seed, int) or seed < 0:
        raise ValueError("seed: a non-negative integer; got %r" % (seed,))
    if (len(grid) != 2 or any(isinstance(g, bool) or not isinstance(g, int) for g in grid)
            or not all(2 <= g <= 4096 for g in grid)):
        raise ValueError("grid: (cos-theta cells, phi cells), two integers in [2, 4096]; got %r" % (grid,))
    if isinstance(threads, bool) or not isinstance(threads, int) or not (0 <= threads <= 1024):
        raise ValueError("threads: an integer in [0, 1024], 0 for all cores; got %r" % (threads,))
    if not (0.0 < alpha < 1.0):
        raise ValueError("alpha: a significance level in (0, 1); got %r" % (alpha,))
    return _scatterlab._check(bsdf, wi_theta, float(wi_phi), samples, seed, tuple(grid), bool(negative_controls),
                              float(alpha), label or "", bool(progress),
                              "" if image_dir is None else str(image_dir), threads)
