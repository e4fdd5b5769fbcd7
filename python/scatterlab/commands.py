"""fit, render and profile: the `scatterlab` commands of the same names as functions that return
their results (docs/python.md, "Fits, renders and profiles").

Every keyword is the command's option of the same name with underscores for dashes
(`per_channel=True` is `--per-channel`), parsed by the command's own option parser, so defaults,
ranges and messages are the command line's; `scatterlab fit --help` lists them. None leaves an
option at its default. Nothing is written: the options that only shape written files or printed
text (--out, --json, and for render --label, --columns, --exposure, --layers) are refused.
"""

import json
import os

import numpy as np

from . import _scatterlab


def _argument(value):
    """A MATERIAL or DATA argument as the command line's text: a dict (a material description) or
    a Material as its JSON, a path as its string."""
    if isinstance(value, dict):
        return json.dumps(value)
    if isinstance(value, _scatterlab.Material):
        return json.dumps(value.description)
    if isinstance(value, (str, os.PathLike)):
        return os.fspath(value)
    raise ValueError("expected a material (dict, Material, JSON text) or a file path; got %r" % (value,))


class FitResult:
    """A fit's outcome: `report` is the dict `scatterlab fit --json` prints ("written" is None),
    `covariance` the fitted parameters' covariance as a (p, p) numpy array in the order of
    `parameters` (NaN where the fit has none), `good` the verdict (the command's exit code 0)."""

    def __init__(self, report, covariance, good):
        self.report = report
        self.covariance = covariance
        self.good = good

    @property
    def material(self):
        """The fitted material as a registry description (a dict; None when the fit produced none)."""
        return self.report["material"]

    @property
    def parameters(self):
        """The fitted parameters, one dict each (name, value, std_dev, lower, upper, at_bound)."""
        return self.report["fit"]["parameters"]

    @property
    def names(self):
        """The parameters' names ("ggx.alpha", "lambertian.albedo.r", ...), in covariance order."""
        return [p["name"] for p in self.parameters]

    @property
    def values(self):
        """The fitted values as a (p,) numpy array."""
        return np.array([p["value"] for p in self.parameters], dtype=np.float64)

    @property
    def errors(self):
        """The standard deviations as a (p,) numpy array (NaN where the fit has none)."""
        return np.array([np.nan if p["std_dev"] is None else p["std_dev"] for p in self.parameters],
                        dtype=np.float64)

    def __repr__(self):
        return "<scatterlab.FitResult %s, %d parameters>" % ("GOOD" if self.good else "POOR", len(self.parameters))


def fit(data, progress=True, **options):
    """Fits registry models to measured data as `scatterlab fit DATA` does and returns a FitResult.

    data: a MERL .binary or RGL .bsdf path, or a material (dict, Material, JSON text or .json
    path) tabulated like a MERL table. options: the command's options, e.g. model="ggx",
    metric="ngan", samples=20000, seed=1, per_channel=True. progress: the progress line on
    stderr. Raises ValueError naming the option, value or file and what is allowed."""
    report, covariance, good = _scatterlab._fit(_argument(data), options, bool(progress))
    return FitResult(report, covariance, good)


def render(material, progress=True, **options):
    """Renders one material sphere as `scatterlab render MATERIAL` does; returns (image, report):
    the image a (height, width, 3) float32 numpy array of linear RGB, top row first, and the
    report the dict --json prints. options: e.g. res="128x96" or (128, 96), spp=64, scene="preview",
    integrator="path", env="white", seed=1, threads=0. Raises ValueError as the command exits 2."""
    if isinstance(options.get("res"), (tuple, list)):
        width, height = options["res"]  # (width, height), the command's "WxH"
        options["res"] = "%sx%s" % (width, height)
    return _scatterlab._render(_argument(material), options, bool(progress))


def profile(material, progress=True, **options):
    """A subsurface material's radial profile as `scatterlab profile MATERIAL --json` prints it,
    as a dict: per channel the total reflectance and the profile averaged over annuli
    (radius_edges, mm); with reference="walk" the random-walk reference beside it; with
    compare=True every profile model against one walk. options: e.g. bins=32, max_radius=8,
    paths=10**5, seed=1."""
    return _scatterlab._profile(_argument(material), options, bool(progress))


def read_exr(path):
    """The R, G and B channels of an EXR file (what `scatterlab render` writes) as a
    (height, width, 3) float32 numpy array."""
    return _scatterlab.read_exr(os.fspath(path))
