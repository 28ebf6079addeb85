"""Cube maps, lat-long maps and 3D textures: Texture.sample3 gives the same
bits as the C library's own program (texsample lookup --cube, --latlong,
--volume) on random 9-float queries for several filters; constant faces and
volumes give the constant; levels, texels and sizes per face and slice;
wrong kinds, shapes and dtypes raise with clear messages."""
import subprocess

import numpy as np
import pytest

import libsample as ls

N = 300          # queries per comparison
CUBE = 8         # face size
LL_W, LL_H = 24, 12
VOL = (5, 6, 7)  # D, H, W: odd sizes, so the box pyramid reads past edges


def _jacobians(rng, n, texels):
    """Random dp/dx, dp/dy from 1/8 texel (magnification) to 16 texels."""
    scale = np.exp2(rng.uniform(-3, 4, (n, 1))) / texels
    return (rng.uniform(-1, 1, (n, 6)) * scale).astype(np.float32)


@pytest.fixture(scope="module")
def case(tmp_path_factory):
    rng = np.random.default_rng(11)
    d = tmp_path_factory.mktemp("kinds")
    dirs = rng.normal(size=(N, 3))
    dirs *= rng.uniform(0.5, 2, (N, 1)) / np.linalg.norm(dirs, axis=1, keepdims=True)  # any length
    env_q = np.concatenate([dirs.astype(np.float32), _jacobians(rng, N, CUBE)], axis=1)
    env_q[::60, 0] = np.nan   # non-finite input: the border colour
    env_q[7, :3] = 0.0        # a zero direction: the border colour too
    vol_q = np.concatenate([rng.uniform(-0.5, 1.5, (N, 3)).astype(np.float32),
                            _jacobians(rng, N, np.array([VOL[2], VOL[1], VOL[0]] * 2))], axis=1)
    vol_q[::60, 1] = np.inf
    c = {
        "faces": rng.random((6, CUBE, CUBE, 4), dtype=np.float32),
        "latlong": rng.random((LL_H, LL_W, 4), dtype=np.float32),
        "volume": rng.random(VOL + (4,), dtype=np.float32),
        "env_q": env_q, "vol_q": vol_q,
    }
    for name in ("faces", "latlong", "volume", "env_q", "vol_q"):
        c[name + "_file"] = str(d / (name + ".raw"))
        c[name].tofile(c[name + "_file"])
    c["out"] = str(d / "out.raw")
    return c


def lookup(texsample, c, source, queries, args):
    cmd = [texsample, "lookup"] + source + ["--queries", c[queries + "_file"], "--out", c["out"]] + args
    subprocess.run(cmd, check=True, capture_output=True)
    return np.fromfile(c["out"], np.float32).reshape(-1, 4)


def same_bits(a, b):
    return a.dtype == b.dtype == np.float32 and a.shape == b.shape and np.array_equal(
        a.view(np.uint32), b.view(np.uint32))


TRILINEAR = ({"min_filter": "linear_mipmap_linear"}, ["--min", "linear_mipmap_linear"])
CUBIC = ({"min_filter": "cubic_mipmap_linear", "mag_filter": "cubic", "cubic": "mitchell"},
         ["--min", "cubic_mipmap_linear", "--mag", "cubic", "--cubic", "mitchell"])
ANISO = ({"min_filter": "linear_mipmap_linear", "footprint": "aniso", "max_anisotropy": 8.0},
         ["--min", "linear_mipmap_linear", "--filter", "aniso", "--aniso", "8"])
EWA = ({"min_filter": "linear_mipmap_linear", "footprint": "ewa"}, ["--min", "linear_mipmap_linear", "--filter", "ewa"])
BN = ({"min_filter": "linear_mipmap_linear", "footprint": "blinn-newell"},
      ["--min", "linear_mipmap_linear", "--filter", "blinn-newell"])
NEAREST_BIASED = ({"min_filter": "nearest_mipmap_nearest", "mag_filter": "nearest", "lod_bias": 0.5,
                   "border_color": (0.25, 0.5, 0.75, 1.0)},
                  ["--min", "nearest_mipmap_nearest", "--mag", "nearest", "--lod-bias", "0.5",
                   "--border", "0.25,0.5,0.75,1"])


@pytest.mark.parametrize("kw, args", [TRILINEAR, CUBIC, ANISO, EWA])
def test_cube_same_bits_as_texsample(texsample, case, kw, args):
    tex = ls.Texture.cube(case["faces"])
    want = lookup(texsample, case, ["--cube", case["faces_file"], "--size", str(CUBE)], "env_q", args)
    assert same_bits(tex.sample3(ls.Sampler(**kw), case["env_q"]), want), kw


@pytest.mark.parametrize("kw, args", [TRILINEAR, BN, NEAREST_BIASED])
def test_latlong_same_bits_as_texsample(texsample, case, kw, args):
    tex = ls.Texture(case["latlong"], wrap="repeat")  # lookup builds the pyramid with its (default) wrap
    want = lookup(texsample, case, ["--latlong", case["latlong_file"], "--w", str(LL_W), "--h", str(LL_H)],
                  "env_q", args)
    assert same_bits(tex.sample3(ls.Sampler(**kw), case["env_q"], latlong=True), want), kw


@pytest.mark.parametrize("wrap, wrap_r, kw, args", [
    ("repeat", "clamp_to_border", *TRILINEAR),
    ("mirrored_repeat", "repeat", *CUBIC),
    ("clamp_to_edge", "mirror_clamp_to_edge", *EWA),
    ("clamp_to_border", "mirrored_repeat", *NEAREST_BIASED),
])
def test_volume_same_bits_as_texsample(texsample, case, wrap, wrap_r, kw, args):
    d, h, w = VOL
    tex = ls.Texture.volume(case["volume"], wrap=(wrap, wrap, wrap_r), mip="lanczos3")
    want = lookup(texsample, case, ["--volume", case["volume_file"], "--w", str(w), "--h", str(h), "--d", str(d),
                                    "--mipgen", "lanczos3"], "vol_q",
                  args + ["--wrap", wrap, "--wrap-r", wrap_r])
    got = tex.sample3(ls.Sampler(wrap_s=wrap, wrap_t=wrap, wrap_r=wrap_r, **kw), case["vol_q"])
    assert same_bits(got, want), (wrap, wrap_r, kw)


def test_query_layouts_and_stats(case):
    """(N, 3, 3), p=/dpdx=/dpdy= keywords, other dtypes and layouts give the
    bits of the C-contiguous float32 (N, 9) array; stats and bias reach C."""
    tex = ls.Texture.cube(case["faces"])
    smp = ls.Sampler(min_filter="linear_mipmap_linear")
    q = case["env_q"]
    want = tex.sample3(smp, q)
    assert same_bits(tex.sample3(smp, q.reshape(N, 3, 3)), want)
    assert same_bits(tex.sample3(smp, p=q[:, :3], dpdx=q[:, 3:6], dpdy=q[:, 6:]), want)
    assert same_bits(tex.sample3(smp, np.asfortranarray(q)), want)
    assert same_bits(tex.sample3(smp, q.astype(np.float64)), want)
    out = np.full((N, 4), 7.0, np.float32)
    assert tex.sample3(smp, q, out=out) is out and same_bits(out, want)
    one = tex.sample3(smp, p=[0, 0, 1])  # a 3-vector: one query, magnification
    assert one.shape == (1, 4) and same_bits(one, tex.sample3(smp, np.array([[0, 0, 1] + [0] * 6], np.float32)))
    r = tex.sample3(smp, q, stats=True)
    assert same_bits(r.rgba, want) and r.drgba_ds is None and r.stats.dtype == ls.STATS_DTYPE
    assert r.stats["level0"][0] == -1 and r.stats["texels"][0] == 0  # the NaN query
    bias = np.full(N, 1.5, np.float32)
    assert same_bits(tex.sample3(smp, q, bias=bias), tex.sample3(smp.replace(lod_bias=1.5), q))
    assert tex.sample3(smp, np.zeros((0, 9), np.float32)).shape == (0, 4)


@pytest.mark.parametrize("footprint", ["none", "aniso", "ewa", "blinn-newell"])
def test_constant_textures_give_the_constant(footprint):
    rng = np.random.default_rng(5)
    value = np.array([0.25, 0.5, 0.75, 1.0], np.float32)
    smp = ls.Sampler(min_filter="linear_mipmap_linear", footprint=footprint, max_anisotropy=8.0, wrap="repeat")
    q = np.concatenate([rng.normal(size=(64, 3)), rng.normal(size=(64, 6)) * 0.3], axis=1).astype(np.float32)
    cube = ls.Texture.cube(np.broadcast_to(value, (6, 4, 4, 4)))
    latlong = ls.Texture(np.broadcast_to(value, (6, 10, 4)))
    vol_q = q.copy()
    vol_q[:, :3] = rng.uniform(-1, 2, (64, 3))
    vol = ls.Texture.volume(np.broadcast_to(value, (3, 5, 4, 4)), mip="kaiser")
    for got in (cube.sample3(smp, q), latlong.sample3(smp, q, latlong=True), vol.sample3(smp, vol_q)):
        assert np.allclose(got, value, rtol=0, atol=1e-6), footprint


def test_cube_levels_texels_and_info():
    rng = np.random.default_rng(2)
    faces = rng.random((6, 8, 8, 3), dtype=np.float32)
    tex = ls.Texture.cube(list(faces))  # six arrays as well as one (6, N, N, C)
    assert tex.info == ls.TextureInfo(8, 8, 3, 4, "float", tex.info.bytes, "cube", 6)
    assert tex.kind == "cube" and tex.level_size(1) == (4, 4) and tex.level_size3(1) == (4, 4, 6)
    levels = tex.levels
    assert [lv.shape for lv in levels] == [(6, n, n, 4) for n in (8, 4, 2, 1)]
    assert np.array_equal(levels[0][..., :3], faces) and np.all(levels[0][..., 3] == 1)
    for k, lv in enumerate(levels):
        n = lv.shape[1]
        want = [[[tex.texel(k, i, j, f) for i in range(n)] for j in range(n)] for f in range(6)]
        assert np.array_equal(lv, np.array(want)), k
    ones = np.ones((6, 2, 2, 1), np.uint8)
    given = ls.Texture.cube_from_levels([np.zeros((6, 4, 4, 1), np.uint8), ones * 255])
    assert given.info.levels == 2 and given.info.format == "unorm8" and np.all(given.level(1)[..., 0] == 1)
    assert ls.Texture.cube(faces, mip=None).info.levels == 1
    assert ls.Texture.cube((faces * 255).astype(np.uint8), srgb=True).info.format == "srgb8"


def test_volume_levels_texels_and_wrap_r():
    rng = np.random.default_rng(4)
    vol = rng.random((5, 6, 7), dtype=np.float32)  # D x H x W, one channel
    tex = ls.Texture.volume(vol)
    assert tex.info == ls.TextureInfo(7, 6, 1, 3, "float", tex.info.bytes, "3d", 5)
    assert tex.level_size(1) == (3, 3) and tex.level_size3(1) == (3, 3, 2) and tex.level_size3(2) == (1, 1, 1)
    levels = tex.levels
    assert [lv.shape for lv in levels] == [(5, 6, 7, 4), (2, 3, 3, 4), (1, 1, 1, 4)]
    assert np.array_equal(levels[0][..., 0], vol)
    for k, lv in enumerate(levels):
        d, h, w = lv.shape[:3]
        want = [[[tex.texel(k, i, j, s) for i in range(w)] for j in range(h)] for s in range(d)]
        assert np.array_equal(lv, np.array(want)), k
    assert tex.texel(0, 6, 5, 4)[0] == vol[4, 5, 6]
    # The pyramid's wrap on r reaches C (sample_mip_params.wrap_r): a sinc
    # kernel reading past r's edges sees other texels.
    a = ls.Texture.volume(vol, mip="lanczos3", wrap=("clamp_to_edge", "clamp_to_edge", "repeat"))
    b = ls.Texture.volume(vol, mip="lanczos3", wrap="clamp_to_edge")
    assert not np.array_equal(a.level(1), b.level(1))
    c = ls.Texture.volume(vol, mip="lanczos3", wrap=("clamp_to_edge", "clamp_to_edge", "clamp_to_edge"))
    assert np.array_equal(b.level(1), c.level(1))
    given = ls.Texture.volume_from_levels([vol, np.full((2, 3, 3), 0.5, np.float32)])
    assert given.info.levels == 2 and np.all(given.level(1)[..., 0] == 0.5)
    assert "3d 7x6x5 x1 float" in repr(tex)


def test_bad_input():
    smp = ls.Sampler()
    flat = ls.Texture(np.ones((4, 8, 4), np.float32))
    cube = ls.Texture.cube(np.ones((6, 4, 4, 4), np.float32))
    vol = ls.Texture.volume(np.ones((2, 4, 4, 4), np.float32))
    q9 = np.zeros((3, 9), np.float32)
    q9[:, 2] = 1
    cases = [
        # wrong kind
        (lambda: flat.sample3(smp, q9), TypeError, "a 2D texture takes .s, t. queries through sample"),
        (lambda: cube.sample3(smp, q9, latlong=True), TypeError, "this texture is a cube map"),
        (lambda: vol.sample3(smp, q9, latlong=True), TypeError, "this texture is a 3D texture"),
        (lambda: cube.sample(smp, np.zeros((3, 6), np.float32)), TypeError, "a cube texture takes 9-float"),
        (lambda: vol.sample(smp, s=0.5, t=0.5), TypeError, "a 3d texture takes 9-float queries .* use sample3"),
        # wrong shapes
        (lambda: cube.sample3(smp, np.zeros((3, 6), np.float32)), ValueError, r"queries: shape \(N x 9\)"),
        (lambda: cube.sample3(smp, p=np.zeros((3, 2))), ValueError, "p: an N x 3 array or a 3-vector"),
        (lambda: cube.sample3(smp, p=np.zeros((3, 3)), dpdx=np.zeros((2, 3))), ValueError, "N x 3 arrays of one N"),
        (lambda: cube.sample3(smp), TypeError, r"give queries \(N x 9\) or p="),
        (lambda: cube.sample3(smp, q9, p=[0, 0, 1]), TypeError, "not both"),
        (lambda: cube.sample3(smp, q9, bias=np.zeros(2)), ValueError, r"bias: shape \(3\) expected"),
        (lambda: cube.sample3(smp, q9, out=np.zeros((3, 4))), ValueError, "out: a writable C-contiguous float32"),
        (lambda: ls.Texture.cube(np.ones((5, 4, 4, 4), np.float32)), ValueError, "six faces .* not 5"),
        (lambda: ls.Texture.cube(np.ones((4, 4), np.float32)), ValueError, r"\(6, N, N\) .* not shape \(4, 4\)"),
        (lambda: ls.Texture.cube(np.ones((6, 4, 5, 4), np.float32)), ls.LibsampleArgumentError,
         "sample_texture_create_cube: "),
        (lambda: ls.Texture.cube([np.ones((4, 4))] * 5 + [np.ones((2, 2))]), ls.LibsampleArgumentError,
         "sample_texture_create_cube: "),
        (lambda: ls.Texture.volume(np.ones((4, 4), np.float32)), ValueError, "D x H x W or D x H x W x C"),
        (lambda: ls.Texture.volume(np.ones((2, 4, 4, 5), np.float32)), ValueError, r"C = 1 to 4, not shape"),
        (lambda: ls.Texture.volume(np.ones((2, 4, 4)), wrap=("repeat", "repeat")), ValueError,
         r"wrap: one wrap mode or 3, \(s, t, r\)"),
        (lambda: ls.Texture.volume_from_levels([np.ones((4, 4, 4)), np.ones((3, 2, 2))]), ls.LibsampleArgumentError,
         "sample_texture_create_3d_levels: "),
        (lambda: ls.Texture.cube_from_levels([]), ValueError, "at least one level"),
        (lambda: vol.texel(0, 0, 0, 2), IndexError, "layer 2 outside level 0's 4 x 4 x 2"),
        (lambda: cube.level_size3(3), IndexError, "level 3: the texture has 3 levels"),
        # wrong dtypes
        (lambda: cube.sample3(smp, q9.astype(np.complex64)), TypeError, "queries: a float32 array"),
        (lambda: cube.sample3(smp, p=[["a", "b", "c"]]), TypeError, "p: real numbers"),
        (lambda: ls.Texture.cube(np.ones((6, 4, 4, 4), np.int32)), TypeError, "float32, float16 or uint8"),
        (lambda: ls.Texture.volume(np.ones((2, 4, 4, 4), np.complex64)), TypeError, "float32, float16 or uint8"),
    ]
    for f, exc, msg in cases:
        with pytest.raises(exc, match=msg):
            f()
    cube.close()
    with pytest.raises(ls.ClosedTextureError):
        cube.sample3(smp, q9)
