"""Texture.sample gives the same bits as the C library's own program
(texsample lookup) on the same texels, queries and sampler state, for every
filter: min filters, mag filters, cubic kinds, footprint filters (with and
without Blinn–Newell's corners), per-query bias."""
import os
import subprocess

import numpy as np
import pytest

import libsample as ls

W, H, N = 37, 24, 400


@pytest.fixture(scope="module")
def case(tmp_path_factory):
    rng = np.random.default_rng(7)
    texels = rng.random((H, W, 4), dtype=np.float32)
    q = np.empty((N, 6), np.float32)
    q[:, :2] = rng.uniform(-0.5, 1.5, (N, 2))
    # Jacobians from 1/8 texel (magnification) to 16 texels, anisotropic.
    scale = np.exp2(rng.uniform(-3, 4, (N, 1))) / np.array([W, H, W, H], np.float32)
    q[:, 2:] = (rng.uniform(-1, 1, (N, 4)) * scale).astype(np.float32)
    q[::50, 0] = np.nan  # non-finite input: the border colour
    corners = (q[:, None, :2] + rng.uniform(-0.05, 0.05, (N, 4, 2))).astype(np.float32)
    bias = rng.uniform(-2, 2, N).astype(np.float32)
    d = tmp_path_factory.mktemp("bits")
    files = {"tex": d / "tex.raw", "q": d / "q.raw", "c": d / "c.raw", "out": d / "out.raw"}
    texels.tofile(files["tex"])
    q.tofile(files["q"])
    corners.tofile(files["c"])
    return texels, q, corners, bias, files


# (Sampler keywords, texsample lookup options)
CONFIGS = [({"min_filter": f, "mag_filter": m}, ["--min", f, "--mag", m])
           for f in ls.names("filter") for m in ("nearest", "linear", "cubic")]
CONFIGS += [({"min_filter": "cubic_mipmap_linear", "mag_filter": "cubic", "cubic": c},
             ["--min", "cubic_mipmap_linear", "--mag", "cubic", "--cubic", c]) for c in ls.names("cubic")]
CONFIGS += [
    ({"min_filter": "linear_mipmap_linear", "footprint": "aniso", "max_anisotropy": 8.0},
     ["--min", "linear_mipmap_linear", "--filter", "aniso", "--aniso", "8"]),
    ({"min_filter": "linear_mipmap_linear", "footprint": "blinn-newell"},
     ["--min", "linear_mipmap_linear", "--filter", "blinn-newell"]),
    ({"min_filter": "linear_mipmap_linear", "footprint": "ewa"},
     ["--min", "linear_mipmap_linear", "--filter", "ewa"]),
    ({"min_filter": "linear_mipmap_linear", "footprint": "ewa", "ewa_kernel": "lanczos2", "options": ["ewa_clamp"]},
     ["--min", "linear_mipmap_linear", "--filter", "ewa", "--ewa-kernel", "lanczos2", "--ewa-clamp"]),
    ({"min_filter": "linear_mipmap_linear", "footprint": "feline"},
     ["--min", "linear_mipmap_linear", "--filter", "feline"]),
    ({"min_filter": "linear_mipmap_linear", "lod_bias": 0.75, "min_lod": 0.5, "max_lod": 3.0,
      "border_color": (0.25, 0.5, 0.75, 1.0)},
     ["--min", "linear_mipmap_linear", "--lod-bias", "0.75", "--min-lod", "0.5", "--max-lod", "3",
      "--border", "0.25,0.5,0.75,1"]),
    ({"min_filter": "cubic_mipmap_linear", "options": ["cubic_clamp"], "base_level": 1, "max_level": 3},
     ["--min", "cubic_mipmap_linear", "--cubic-clamp", "--base-level", "1", "--max-level", "3"]),
]
WRAPS = ["repeat", "clamp_to_border", "mirror_clamp_to_edge"]


def lookup(texsample, files, args, corners=False):
    cmd = [texsample, "lookup", "--raw", str(files["tex"]), "--w", str(W), "--h", str(H),
           "--queries", str(files["q"]), "--out", str(files["out"])] + args
    if corners:
        cmd += ["--corners", str(files["c"])]
    subprocess.run(cmd, check=True, capture_output=True)
    return np.fromfile(files["out"], np.float32).reshape(-1, 4)


@pytest.mark.parametrize("k", range(len(CONFIGS)))
def test_same_bits_as_texsample(texsample, case, k):
    texels, q, _, _, files = case
    kw, args = CONFIGS[k]
    wrap = WRAPS[k % len(WRAPS)]
    tex = ls.Texture(texels, wrap=wrap)
    got = tex.sample(ls.Sampler(wrap=wrap, **kw), q)
    want = lookup(texsample, files, args + ["--wrap", wrap])
    assert got.dtype == np.float32 and got.shape == (N, 4)
    assert np.array_equal(got.view(np.uint32), want.view(np.uint32)), kw


def test_corners_same_bits(texsample, case):
    texels, q, corners, _, files = case
    tex = ls.Texture(texels, wrap="repeat")
    smp = ls.Sampler(wrap="repeat", min_filter="linear_mipmap_linear", footprint="blinn-newell")
    want = lookup(texsample, files, ["--wrap", "repeat", "--filter", "blinn-newell"], corners=True)
    assert np.array_equal(tex.sample(smp, q, corners=corners).view(np.uint32), want.view(np.uint32))
    flat = tex.sample(smp, q, corners=corners.reshape(N, 8))
    assert np.array_equal(flat.view(np.uint32), want.view(np.uint32))


def test_per_query_bias_is_the_sampler_bias(case):
    """A per-query bias b gives what a sampler with lod_bias = b gives."""
    texels, q, _, bias, _ = case
    tex = ls.Texture(texels, wrap="repeat")
    smp = ls.Sampler(wrap="repeat", min_filter="linear_mipmap_linear")
    got = tex.sample(smp, q[:40], bias=np.full(40, bias[0]))
    want = tex.sample(smp.replace(lod_bias=float(bias[0])), q[:40])
    assert np.array_equal(got.view(np.uint32), want.view(np.uint32))
    assert not np.array_equal(tex.sample(smp, q, bias=bias), tex.sample(smp, q))


def test_keyword_queries_and_copies(case):
    """s=, t=, ... and (N, 6) arrays of any layout or real dtype give the
    same bits as the C-contiguous float32 array passed as it is."""
    texels, q, _, _, _ = case
    tex = ls.Texture(texels)
    smp = ls.Sampler(min_filter="linear_mipmap_linear")
    want = tex.sample(smp, q)
    cols = dict(zip(("s", "t", "dsdx", "dtdx", "dsdy", "dtdy"), q.T))
    assert np.array_equal(tex.sample(smp, **cols), want, equal_nan=True)
    assert np.array_equal(tex.sample(smp, np.asfortranarray(q)), want, equal_nan=True)
    assert np.array_equal(tex.sample(smp, q.astype(np.float64)), want, equal_nan=True)
    wide = np.zeros((N, 12), np.float32)
    wide[:, ::2] = q
    assert np.array_equal(tex.sample(smp, wide[:, ::2]), want, equal_nan=True)
    out = np.full((N, 4), 7.0, np.float32)
    assert tex.sample(smp, q, out=out) is out
    assert np.array_equal(out, want, equal_nan=True)
    # Scalars broadcast: magnification at one point.
    one = tex.sample(smp, s=0.3, t=0.6)
    assert one.shape == (1, 4)
    assert np.array_equal(one[0], tex.sample(smp, np.array([[0.3, 0.6, 0, 0, 0, 0]], np.float32))[0])


def test_derivatives_and_stats(case):
    texels, q, _, _, _ = case
    tex = ls.Texture(texels, wrap="repeat")
    mag = np.zeros((3, 6), np.float32)
    # Between texel centres (u = i + 1), where a small step stays in one cell.
    mag[:, :2] = np.array([[12, 9], [19, 13], [29, 4]], np.float32) / np.array([W, H], np.float32)
    r = tex.sample(ls.Sampler(wrap="repeat", mag_filter="nearest"), mag, derivatives=True, stats=True)
    assert np.array_equal(r.drgba_ds, np.zeros((3, 4), np.float32))  # NEAREST: 0 (sample.h)
    assert list(r.stats["texels"]) == [1, 1, 1] and list(r.stats["level0"]) == [0, 0, 0]
    r = tex.sample(ls.Sampler(wrap="repeat", mag_filter="linear"), mag, derivatives=True, stats=True)
    assert list(r.stats["texels"]) == [4, 4, 4] and list(r.stats["level1"]) == [-1, -1, -1]
    # Bilinear: the s-derivative of a linear blend, a finite difference.
    h = 1e-3
    step = mag.copy()
    step[:, 0] += h
    fd = (tex.sample(ls.Sampler(wrap="repeat"), step) - r.rgba) / h
    assert np.allclose(r.drgba_ds, fd, rtol=1e-2, atol=1e-2)
    nan = tex.sample(ls.Sampler(), q[:1] * np.nan, stats=True)
    assert nan.stats["level0"][0] == -1


def test_empty_batch(case):
    tex = ls.Texture(case[0])
    assert tex.sample(ls.Sampler(), np.zeros((0, 6), np.float32)).shape == (0, 4)
