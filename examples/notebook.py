# %% [markdown]
# # scatterlab from Python: a walk-through
#
# Run it as a script (`PYTHONPATH=build/release/python /usr/bin/python3 examples/notebook.py OUT`)
# or cell by cell in any editor that reads `# %%` cells. It evaluates a registry material on numpy
# arrays, writes a BSDF in numpy and checks its sampling with the statistical kit (and sees the
# kit reject a broken copy), fits a model to tabulated data, renders a sphere and compares a
# subsurface profile with its random-walk reference; the figure goes to OUT/notebook.png.
# docs/python.md documents every call used here.

# %%
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")  # no display needed
import matplotlib.pyplot as plt
import numpy as np

import scatterlab as sl

out = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "notebook-output")
out.mkdir(parents=True, exist_ok=True)
figure, axes = plt.subplots(2, 2, figsize=(11, 9))

# %% [markdown]
# ## 1. A registry material on arrays
# Directions are (N, 3) float64 rows in the local frame (z is the normal). Here f cos(theta_o) of
# a rough gold-like conductor in the plane of incidence, for three roughnesses.

# %%
theta_o = np.radians(np.linspace(-89, 89, 357))
wo = np.stack([np.sin(theta_o), np.zeros_like(theta_o), np.cos(theta_o)], axis=1)
wi = np.array([np.sin(np.radians(30)), 0.0, np.cos(np.radians(30))])  # broadcast to every row
for alpha in (0.1, 0.2, 0.4):
    m = sl.material({"type": "conductor", "alpha": alpha})
    f = m.eval(wi, wo)  # (N, 3) linear RGB
    axes[0, 0].plot(np.degrees(theta_o), f[:, 1] * np.abs(wo[:, 2]), label="alpha %.1f" % alpha)
axes[0, 0].set(title="conductor, wi at 30 deg: f cos(theta_o), green", xlabel="theta_o (deg)")
axes[0, 0].legend()


# %% [markdown]
# ## 2. Your own BSDF, checked by the kit
# Any object with eval, pdf and sample on numpy arrays can be checked (docs/python.md, "The kit on
# any object"). A Lambertian sampled by Malley's method passes; a copy that draws directions
# uniformly over the hemisphere but still reports the cosine density is rejected by the
# chi-square test, although every value it returns is self-consistent.

# %%
class Lambertian:
    def __init__(self, albedo=0.7, uniform_draw=False):
        self.albedo = albedo
        self.uniform_draw = uniform_draw

    def eval(self, wi, wo):  # (N,): grey, broadcast over RGB
        return np.where((wi[:, 2] > 0) & (wo[:, 2] > 0), self.albedo / np.pi, 0.0)

    def pdf(self, wi, wo):
        return np.where((wi[:, 2] > 0) & (wo[:, 2] > 0), wo[:, 2] / np.pi, 0.0)

    def sample(self, wi, u_lobe, u):
        cos_theta = u[:, 0] if self.uniform_draw else np.sqrt(u[:, 0])
        sin_theta = np.sqrt(1.0 - cos_theta**2)
        phi = 2 * np.pi * u[:, 1]
        wo = np.stack([sin_theta * np.cos(phi), sin_theta * np.sin(phi), cos_theta], axis=1)
        pdf = self.pdf(wi, wo)
        valid = pdf > 0
        weight = np.where(valid, self.eval(wi, wo) * wo[:, 2] / np.where(valid, pdf, 1.0), 0.0)
        return wo, np.repeat(weight[:, None], 3, axis=1), pdf, valid


good = sl.check(Lambertian(), wi_theta=(45,), samples=200_000, label="numpy lambertian", progress=False)
broken = sl.check(Lambertian(uniform_draw=True), wi_theta=(45,), samples=200_000, label="uniform draw",
                  progress=False)
print(good)
print(broken)
assert good.passed and not broken.passed
chi2 = [row for row in good.rows if row["test"] == "chi2"]
axes[0, 1].bar([str(row["wi_theta"]) for row in chi2], [row["p_value"] for row in chi2], label="Lambertian")
axes[0, 1].axhline(chi2[0]["threshold"], color="k", lw=0.8, label="pass limit")
axes[0, 1].set(title="chi-square p-values of the numpy Lambertian", xlabel="wi theta (deg)", yscale="log")
axes[0, 1].legend()

# %% [markdown]
# ## 3. A fit with error bars
# Data tabulated from a known material, fitted with the same model family: the parameters come
# back with their standard deviations and the covariance as a numpy array.

# %%
truth = {"type": "blend", "weight": 0.5, "materials": [
    {"type": "lambertian", "albedo": 0.4},
    {"type": "ngan-cook-torrance", "albedo": 0.4, "eta": 0.3, "roughness": 0.1}]}
fit = sl.fit(truth, model="lambertian+ngan-cook-torrance", metric="low-log", samples=20000, grid_points=64,
             starts=2, progress=False)
print(fit)
for p in fit.parameters:
    print("  %-36s %.6g" % (p["name"], p["value"]))
assert fit.good

# %% [markdown]
# ## 4. A rendered sphere
# The path tracer's image as a float32 array of linear RGB, shown with a plain sRGB-like curve.

# %%
image, report = sl.render({"type": "conductor", "alpha": 0.2}, res="96x96", spp=16, progress=False)
assert report["dropped_samples"] == 0
axes[1, 0].imshow(np.clip(image, 0, 1) ** (1 / 2.2))
axes[1, 0].set(title="conductor alpha 0.2, 16 spp", xticks=[], yticks=[])

# %% [markdown]
# ## 5. A subsurface profile against its random-walk reference
# The default profile (Burley's) of the default medium, averaged over annuli, beside the
# half-space random walk that is its ground truth (docs/validation.md section 6).

# %%
profile = sl.profile({"type": "subsurface"}, reference="walk", paths=100_000, bins=16, max_radius=4,
                     progress=False)
edges = np.array(profile["radius_edges"])
middle = 0.5 * (edges[1:] + edges[:-1])
red = profile["channels"][0]
axes[1, 1].loglog(middle, red["profile"], label=profile["profile_model"])
axes[1, 1].loglog(middle, red["walk"]["profile"], "o", ms=3, label="random walk")
axes[1, 1].set(title="red channel R(r), mm^-2", xlabel="r (mm)")
axes[1, 1].legend()

figure.tight_layout()
figure.savefig(out / "notebook.png", dpi=80)
print("wrote", out / "notebook.png")
