"""Textures: formats, levels, files, and the lifetime of the C object."""
import gc
import threading

import numpy as np
import pytest

import libsample as ls

SMP = ls.Sampler(min_filter="linear_mipmap_linear", wrap="repeat")


def queries(n=64, seed=1):
    rng = np.random.default_rng(seed)
    q = np.zeros((n, 6), np.float32)
    q[:, :2] = rng.random((n, 2))
    q[:, 2] = q[:, 5] = 0.05
    return q


def test_formats_and_info():
    a = np.linspace(0, 1, 8 * 6 * 3, dtype=np.float32).reshape(6, 8, 3)
    t = ls.Texture(a)
    assert t.info == ls.TextureInfo(8, 6, 3, 4, "float", t.info.bytes, "2d")
    assert ls.Texture(a.astype(np.float16)).info.format == "half"
    assert ls.Texture((a * 255).astype(np.uint8)).info.format == "unorm8"
    assert ls.Texture((a * 255).astype(np.uint8), srgb=True).info.format == "srgb8"
    assert ls.Texture(a, format="half").info.format == "half"
    assert ls.Texture(a.astype(np.float64)).info.format == "float"
    grey = ls.Texture(a[:, :, 0], mip=None)
    assert (grey.info.channels, grey.info.levels) == (1, 1)
    assert ls.Texture(a, max_levels=2).info.levels == 2


def test_levels_are_decoded_texels():
    """Texture.level(k) holds sample_texture_texel's values, and level 0 of a
    float RGBA texture is the array itself."""
    rng = np.random.default_rng(3)
    a = rng.random((10, 13, 4), dtype=np.float32)
    t = ls.Texture(a)
    levels = t.levels
    assert [lv.shape for lv in levels] == [(10, 13, 4), (5, 6, 4), (2, 3, 4), (1, 1, 4)]
    assert np.array_equal(levels[0], a)
    for src in (a[:, :, :2].astype(np.float16), (a * 255).astype(np.uint8)):
        for srgb in ((False, True) if src.dtype == np.uint8 else (False,)):
            u = ls.Texture(src, srgb=srgb)
            for k, lv in enumerate(u.levels):
                h, w = lv.shape[:2]
                want = np.array([[u.texel(k, i, j) for i in range(w)] for j in range(h)])
                assert np.array_equal(lv, want)
    assert np.array_equal(ls.Texture(a[:, :, 0]).level(0)[2, 3], [a[2, 3, 0], 0, 0, 1])


def test_from_levels():
    base = np.ones((4, 4, 1), np.float32)
    t = ls.Texture.from_levels([base, np.full((2, 2, 1), 0.5, np.float32)])
    assert t.info.levels == 2 and t.level(1)[0, 0, 0] == 0.5
    with pytest.raises(ls.LibsampleArgumentError, match="sample_texture_create_levels"):
        ls.Texture.from_levels([base, np.ones((3, 3, 1), np.float32)])


def test_load(testimage):
    try:
        t = ls.Texture.load(testimage)
    except ImportError:
        pytest.skip("libsample_io not built")
    assert (t.info.width, t.info.height, t.info.channels, t.info.format) == (19, 13, 3, "srgb8")
    with pytest.raises(ls.LibsampleError, match="no/such/file.png"):
        ls.Texture.load("no/such/file.png")


def test_outlives_its_array():
    """The library copies the texels: changing or dropping the source array
    changes nothing."""
    a = np.random.default_rng(5).random((16, 16, 4), dtype=np.float32)
    t = ls.Texture(a)
    want = t.sample(SMP, queries())
    a[:] = 0
    del a
    gc.collect()
    assert np.array_equal(t.sample(SMP, queries()), want)


def test_closed_texture_raises():
    t = ls.Texture(np.ones((4, 4), np.float32))
    with t as same:
        assert same is t
    assert t.closed
    for use in (lambda: t.sample(SMP, queries()), lambda: t.info, lambda: t.levels, lambda: t.texel(0, 0, 0)):
        with pytest.raises(ls.ClosedTextureError, match="closed"):
            use()
    t.close()  # again: nothing
    assert "closed" in repr(t)


def test_close_while_sampling():
    """close() from another thread while batches run: the running batches
    finish on a live texture, later ones raise; no crash."""
    t = ls.Texture(np.random.default_rng(2).random((64, 64, 4), dtype=np.float32))
    q = queries(20000)
    want = t.sample(SMP, q)
    results, errors = [], []

    def work():
        for _ in range(20):
            try:
                results.append(np.array_equal(t.sample(SMP, q), want))
            except ValueError:
                errors.append(1)

    threads = [threading.Thread(target=work) for _ in range(3)]
    for th in threads:
        th.start()
    t.close()
    for th in threads:
        th.join()
    assert all(results) and len(results) + len(errors) == 60


def test_no_references_kept():
    """Sampling keeps no reference to its inputs, and its result owns its
    memory (no view into a temporary)."""
    import sys

    t = ls.Texture(np.ones((8, 8, 4), np.float32))
    q = queries(16)
    before = sys.getrefcount(q)
    for _ in range(100):
        r = t.sample(SMP, q)
    assert sys.getrefcount(q) == before
    assert r.base is None and r.flags.owndata
    lv = t.level(0)
    assert lv.base is None or lv.base.base is None  # a reshape of an array it owns
