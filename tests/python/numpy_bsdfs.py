"""BSDFs written in numpy, as a user of the Python package writes them, for the kit's tests:
the same signatures as scatterlab's materials (docs/python.md, "The kit on any object")."""

import numpy as np


def _mirror(wi):
    return wi * np.array([-1.0, -1.0, 1.0])


def _frame(n):
    """Two unit tangents completing n to an orthonormal basis, for every row (Duff et al. 2017,
    "Building an Orthonormal Basis, Revisited", listing 3)."""
    sign = np.where(n[:, 2] >= 0.0, 1.0, -1.0)
    a = -1.0 / (sign + n[:, 2])
    b = n[:, 0] * n[:, 1] * a
    t = np.stack([1.0 + sign * n[:, 0] ** 2 * a, sign * b, -sign * n[:, 0]], axis=1)
    s = np.stack([b, sign + n[:, 1] ** 2 * a, -n[:, 1]], axis=1)
    return t, s


class PhongLobe:
    """The modified Phong lobe (Lafortune and Willems 1994, eq. 4): f = rho (n + 2) / (2 pi)
    cos^n(a), a the angle between wo and the mirror direction of wi; reciprocal, albedo <= rho.
    Sampled exactly: cos(a) = u0^(1 / (n + 1)) gives pdf = (n + 1) / (2 pi) cos^n(a) per solid
    angle around the mirror direction; directions below the horizon fail.

    pdf_exponent != exponent is a deliberately broken variant: sample() still draws the lobe of
    `exponent` but reports, and pdf() returns, the density of `pdf_exponent`, with the weight
    f |cos wo| / pdf computed from it, so every per-sample identity holds and only the
    histogram can tell."""

    def __init__(self, exponent=20.0, albedo=0.8, pdf_exponent=None):
        self.exponent = float(exponent)
        self.albedo = float(albedo)
        self.pdf_exponent = self.exponent if pdf_exponent is None else float(pdf_exponent)

    def _cos_to_mirror(self, wi, wo):
        return np.clip(np.sum(_mirror(wi) * wo, axis=1), 0.0, 1.0)

    def _above(self, wi, wo):
        return (wi[:, 2] > 0.0) & (wo[:, 2] > 0.0)

    def eval(self, wi, wo):
        c = self._cos_to_mirror(wi, wo)
        f = self.albedo * (self.exponent + 2.0) / (2.0 * np.pi) * c ** self.exponent
        return np.where(self._above(wi, wo), f, 0.0)  # grey: (N,) broadcasts over RGB

    def pdf(self, wi, wo):
        c = self._cos_to_mirror(wi, wo)
        p = (self.pdf_exponent + 1.0) / (2.0 * np.pi) * c ** self.pdf_exponent
        return np.where(self._above(wi, wo), p, 0.0)

    def sample(self, wi, u_lobe, u):
        cos_a = u[:, 0] ** (1.0 / (self.exponent + 1.0))
        sin_a = np.sqrt(np.maximum(0.0, 1.0 - cos_a ** 2))
        phi = 2.0 * np.pi * u[:, 1]
        m = _mirror(wi)
        t, s = _frame(m)
        wo = (sin_a * np.cos(phi))[:, None] * t + (sin_a * np.sin(phi))[:, None] * s + cos_a[:, None] * m
        wo /= np.linalg.norm(wo, axis=1)[:, None]
        valid = self._above(wi, wo)
        pdf = self.pdf(wi, wo)
        with np.errstate(divide="ignore", invalid="ignore"):
            weight = np.where(valid & (pdf > 0.0), self.eval(wi, wo) * wo[:, 2] / pdf, 0.0)
        return wo, np.repeat(weight[:, None], 3, axis=1), pdf, valid & (pdf > 0.0)


class WhiteLambertian:
    """f = albedo / pi, cosine-sampled (Malley's method); lossless = True: a white one has
    albedo 1 at every wi, which the furnace row checks."""

    lossless = True

    def __init__(self, albedo=1.0):
        self.albedo = float(albedo)

    def eval(self, wi, wo):
        return np.where((wi[:, 2] > 0.0) & (wo[:, 2] > 0.0), self.albedo / np.pi, 0.0)

    def pdf(self, wi, wo):
        return np.where((wi[:, 2] > 0.0) & (wo[:, 2] > 0.0), np.maximum(wo[:, 2], 0.0) / np.pi, 0.0)

    def sample(self, wi, u_lobe, u):
        r = np.sqrt(u[:, 0])
        phi = 2.0 * np.pi * u[:, 1]
        z = np.sqrt(np.maximum(0.0, 1.0 - u[:, 0]))
        wo = np.stack([r * np.cos(phi), r * np.sin(phi), z], axis=1)
        valid = (wi[:, 2] > 0.0) & (z > 0.0)
        weight = np.where(valid, self.albedo, 0.0)
        return wo, np.repeat(weight[:, None], 3, axis=1), self.pdf(wi, wo), valid


class Mirror:
    """A perfect mirror: one delta lobe (delta = True), chosen with `probability`; a mirror that
    claims a probability other than the fraction of samples it returns is broken."""

    delta = True

    def __init__(self, probability=1.0, claimed=None):
        self.probability = float(probability)
        self.claimed = self.probability if claimed is None else float(claimed)

    def eval(self, wi, wo):
        return np.zeros(len(wi))

    def pdf(self, wi, wo):
        return np.zeros(len(wi))

    def sample(self, wi, u_lobe, u):
        wo = _mirror(wi)
        valid = (wi[:, 2] > 0.0) & (u_lobe < self.probability)
        pdf = np.full(len(wi), self.claimed)
        weight = np.where(valid, self.probability / self.claimed, 0.0)
        return wo, np.repeat(weight[:, None], 3, axis=1), pdf, valid, np.ones(len(wi), dtype=bool)


class DiffuseTransmitter:
    """Lambertian reflection `reflectance` / pi on the incident side and Lambertian transmission
    `transmittance` / pi on the other (transmission = True), cosine-sampled on the side chosen
    by u_lobe in proportion to the two; reciprocal, from above and from below alike."""

    transmission = True

    def __init__(self, reflectance=0.5, transmittance=0.3):
        self.r = float(reflectance)
        self.t = float(transmittance)

    def _same_side(self, wi, wo):
        return wi[:, 2] * wo[:, 2] > 0.0

    def eval(self, wi, wo):
        touching = (wi[:, 2] == 0.0) | (wo[:, 2] == 0.0)
        return np.where(touching, 0.0, np.where(self._same_side(wi, wo), self.r, self.t) / np.pi)

    def pdf(self, wi, wo):
        touching = (wi[:, 2] == 0.0) | (wo[:, 2] == 0.0)
        lobe = np.where(self._same_side(wi, wo), self.r, self.t) / (self.r + self.t)
        return np.where(touching, 0.0, lobe * np.abs(wo[:, 2]) / np.pi)

    def sample(self, wi, u_lobe, u):
        r = np.sqrt(u[:, 0])
        phi = 2.0 * np.pi * u[:, 1]
        z = np.sqrt(np.maximum(0.0, 1.0 - u[:, 0]))
        side = np.sign(wi[:, 2]) * np.where(u_lobe < self.r / (self.r + self.t), 1.0, -1.0)
        wo = np.stack([r * np.cos(phi), r * np.sin(phi), side * z], axis=1)
        valid = (wi[:, 2] != 0.0) & (z > 0.0)
        weight = np.where(valid, self.r + self.t, 0.0)
        return wo, np.repeat(weight[:, None], 3, axis=1), self.pdf(wi, wo), valid


class MaterialAsObject:
    """A scatterlab Material seen only through its eval, pdf and sample methods: the kit then runs
    on it through the Python-object path, which must reproduce the material's own report."""

    def __init__(self, material):
        self.material = material

    def eval(self, wi, wo):
        return self.material.eval(wi, wo)

    def pdf(self, wi, wo):
        return self.material.pdf(wi, wo)

    def sample(self, wi, u_lobe, u):
        return self.material.sample(wi, u_lobe, u)
