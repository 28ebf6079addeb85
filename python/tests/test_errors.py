"""Bad input raises exceptions with clear messages, never crashes."""
import numpy as np
import pytest

import libsample as ls

TEX = np.ones((4, 4, 4), np.float32)


@pytest.mark.parametrize("array, exc, msg", [
    (np.ones((4, 4, 4), np.complex64), TypeError, "float32, float16 or uint8"),
    (np.ones((4, 4, 4), np.int32), TypeError, "not int32"),
    (np.array([["a"]]), TypeError, "float32, float16 or uint8"),
    (np.ones((4, 4, 5), np.float32), ValueError, r"C = 1 to 4, not shape \(4, 4, 5\)"),
    (np.ones(4, np.float32), ValueError, "H x W or H x W x C"),
    (np.ones((0, 4), np.float32), ls.LibsampleArgumentError, "sample_texture_create"),
])
def test_bad_texels(array, exc, msg):
    with pytest.raises(exc, match=msg):
        ls.Texture(array)


def test_bad_texture_options():
    with pytest.raises(TypeError, match="format 'unorm8' stores uint8; the array is float32"):
        ls.Texture(TEX, format="unorm8")
    with pytest.raises(ValueError, match="format: 'f32' is not one of float, half, unorm8, srgb8"):
        ls.Texture(TEX, format="f32")
    with pytest.raises(ValueError, match="srgb=True needs uint8"):
        ls.Texture(TEX, srgb=True)
    with pytest.raises(ValueError, match="mip: unknown mipgen 'gauss'; one of: none, box"):
        ls.Texture(TEX, mip="gauss")


@pytest.mark.parametrize("kw, exc, msg", [
    ({"min_filter": "trilinear"}, ValueError, "min_filter: unknown filter 'trilinear'; one of: nearest,"),
    ({"wrap_s": 8}, ValueError, "wrap_s: 8 is not a wrap"),
    ({"wrap_s": 1.5}, TypeError, "wrap_s: a wrap name"),
    ({"lod_bias": float("nan")}, ValueError, "lod_bias is NaN"),
    ({"max_anisotropy": float("nan")}, ValueError, "max_anisotropy is NaN"),
    ({"border_color": (0, 0, float("nan"), 1)}, ValueError, "border_color is NaN"),
    ({"border_color": (0, 0, 0)}, ValueError, "4 floats"),
    ({"max_anisotropy": 0.5}, ls.LibsampleArgumentError, "max_anisotropy=0.5"),
    ({"min_lod": 2.0, "max_lod": 1.0}, ValueError, "sample_sampler_validate rejects"),
    ({"lod_bias": float("inf")}, ValueError, "lod_bias=inf"),
    ({"mag_filter": "linear_mipmap_linear"}, ValueError, "mag_filter='linear_mipmap_linear'"),
    ({"options": ["fast"]}, ValueError, "options: unknown option 'fast'"),
    ({"colour": 1}, TypeError, "unknown keyword 'colour'"),
    ({"base_level": 1.0}, TypeError, "base_level: an int"),
])
def test_bad_sampler(kw, exc, msg):
    with pytest.raises(exc, match=msg):
        ls.Sampler(**kw)


def test_enums_by_int_and_name():
    s = ls.Sampler(min_filter=5, wrap="clamp_to_edge", footprint="ewa", options=["cubic_clamp", "aniso_pow2"])
    assert (s.min_filter, s.wrap_t, s.footprint, s.options) == ("linear_mipmap_linear", "clamp_to_edge", "ewa", 12)
    assert ls.Sampler(min_filter="linear_mipmap_linear") == s.replace(wrap="repeat", footprint=0, options=0)


@pytest.mark.parametrize("q, exc, msg", [
    (np.ones((3, 5), np.float32), ValueError, r"queries: shape \(N x 6\) expected, not \(3, 5\)"),
    (np.ones(6, np.float32), ValueError, "queries: shape"),
    (np.ones((3, 6), np.complex64), TypeError, "queries: a float32 array"),
    ([["a"] * 6], TypeError, "queries: a float32 array"),
])
def test_bad_queries(q, exc, msg):
    with pytest.raises(exc, match=msg):
        ls.Texture(TEX).sample(ls.Sampler(), q)


def test_bad_sample_arguments():
    t = ls.Texture(TEX)
    q = np.zeros((3, 6), np.float32)
    with pytest.raises(ValueError, match=r"corners: shape \(3 x 8\) expected"):
        t.sample(ls.Sampler(), q, corners=np.zeros((3, 6)))
    with pytest.raises(ValueError, match=r"bias: shape \(3\) expected"):
        t.sample(ls.Sampler(), q, bias=np.zeros(2))
    with pytest.raises(ValueError, match="out: a writable C-contiguous float32 array of shape"):
        t.sample(ls.Sampler(), q, out=np.zeros((3, 4)))
    with pytest.raises(ValueError, match="arrays of one length N"):
        t.sample(ls.Sampler(), s=[0.1, 0.2], t=[0.1, 0.2, 0.3])
    with pytest.raises(TypeError, match="give queries"):
        t.sample(ls.Sampler())
    with pytest.raises(TypeError, match="a libsample.Sampler"):
        t.sample("trilinear", q)


def test_library_error_carries_the_message():
    with pytest.raises(ls.LibsampleError) as e:
        ls.Texture(np.ones((1, 70000), np.float32))
    assert e.value.status == 3 and e.value.status_name == "too large"
    assert "70000" in e.value.message and isinstance(e.value, ValueError)


def test_nan_queries_give_the_border():
    """NaN coordinates are not an error in libsample: the border colour
    (DESIGN §10), as in C."""
    t = ls.Texture(TEX)
    r = t.sample(ls.Sampler(border_color=(1, 0, 0.5, 1)), s=[np.nan, 0.5], t=[0.5, np.inf])
    assert np.array_equal(r, [[1, 0, 0.5, 1], [1, 0, 0.5, 1]])
