"""libsample.freq and libsample.compare: texsample freq's and compare's
measurements from Python, on registry filters and on Python callables."""
import numpy as np
import pytest

import libsample as ls


@pytest.fixture(autouse=True, scope="module")
def measure_library():
    """libsample_measure is built with the tools (SAMPLE_BUILD_IO)."""
    try:
        ls.measure._lib_measure()
    except ImportError as e:
        pytest.skip(str(e).splitlines()[0])

# A small sweep: 64-texel gratings, F step 1/8 cycle/pixel.
SMALL = dict(theta=[0.0], n=64, f_step=1 / 8, f_max=2.0, width=16, rows=1, phases=64)


def nearest(queries, texture):
    """Nearest texel of the base level, in numpy."""
    lv = texture.level(0)
    h, w = lv.shape[:2]
    i = np.floor(queries[:, 0] * w).astype(int) % w
    j = np.floor(queries[:, 1] * h).astype(int) % h
    return lv[j, i]


def box(b):
    """The b x b box of base texels around the nearest one: the average of
    b nearest lookups one texel apart (REPEAT)."""
    def f(queries, texture):
        lv = texture.level(0)
        h, w = lv.shape[:2]
        i = np.floor(queries[:, 0] * w).astype(int)
        j = np.floor(queries[:, 1] * h).astype(int)
        acc = np.zeros((len(queries), 4))
        for dj in range(b):
            for di in range(b):
                acc += lv[(j + dj - b // 2) % h, (i + di - b // 2) % w]
        return acc / (b * b)
    f.__name__ = "box%d" % b
    return f


def test_callable_box_reproduces_the_closed_form():
    """Random offsets make the measured response the Fourier transform of
    the filter's kernel (doc/frequency-tests.md §4.3): for nearest followed
    by a b-texel box, sinc(f) · sin(π f b) / (b sin(π f)) along θ = 0,
    within 4 standard errors (+1e-3 for float)."""
    b = 4
    r = ls.freq(box(b), m=[4.0], **SMALL)
    F, amp, se = r.curve("box4", 4.0)
    f = r.points["f"]
    assert len(F) >= 10 and np.array_equal(F, f * 4.0)
    with np.errstate(invalid="ignore", divide="ignore"):
        want = np.abs(np.sinc(f) * np.where(f == 0, 1.0, np.sin(np.pi * f * b) / (b * np.sin(np.pi * f))))
    assert np.all(np.abs(amp - want) <= 4 * se + 1e-3), np.c_[F, amp, want, se]
    s = r.summary("box4")
    assert s.pass_band < 0.9 and s.aliasing < 0.2 and np.isnan(s.texels)


def test_callable_matches_the_library_filter():
    """nearest written in numpy measures as libsample's nearest, point for
    point: the same queries, the same texels, the same fit."""
    r = ls.freq({"mine": nearest, "lib": "nearest"}, m=[1.5, 4.0], **SMALL)
    assert r.filters == ["mine", "lib"]
    for m in r.m:
        F0, a0, _ = r.curve("mine", m)
        F1, a1, _ = r.curve("lib", m)
        assert np.array_equal(F0, F1) and np.array_equal(a0, a1)
    assert r.summary("lib").texels == 1.0
    assert r.summary("mine", m=4.0) == r.summary(0, m=4.0)


def test_freq_errors():
    with pytest.raises(ValueError, match="'gaussian' is not a filter of the registry"):
        ls.freq("gaussian", m=[2.0], **SMALL)

    def broken(queries, texture):
        raise ZeroDivisionError("inside the filter")

    with pytest.raises(ZeroDivisionError, match="inside the filter"):
        ls.freq(broken, m=[2.0], **SMALL)
    with pytest.raises(ValueError, match=r"returned float64 \(.*\) for .* queries; \(N, 4\)"):
        ls.freq(lambda q, t: np.zeros((len(q), 3)), m=[2.0], **SMALL)
    with pytest.raises(ValueError, match="r = 0.5; anisotropy ratios are >= 1"):
        ls.freq("nearest", m=[2.0], r=[0.5], **{k: v for k, v in SMALL.items()})
    kept = []
    ls.freq(lambda q, t: (kept.append(t), np.zeros((len(q), 4)))[1], m=[8.0], **SMALL)
    with pytest.raises(ls.ClosedTextureError):
        kept[0].level(0)  # the grating is lent for the call only


def trilinear(queries, texture):
    """Trilinear through libsample itself, as a callable."""
    return texture.sample(ls.Sampler(min_filter="linear_mipmap_linear", wrap="repeat"), queries)


def test_compare_callable_and_registry():
    """A callable that samples as the registry's trilinear gives its picture
    and its numbers; the truth, mask and metrics are texsample compare's."""
    r = ls.compare({"py": trilinear, "c": "trilinear", "bn": "blinn-newell-corners", "near": "nearest"},
                   scene="plane", size=48, truth=4, threads=2)
    assert r.filters == ["py", "c", "bn", "near"]
    assert r.truth.shape == (48, 48, 4) and r.mask.dtype == bool and 0 < r.mask.sum() < 48 * 48
    assert np.array_equal(r.images["py"], r.images["c"])
    py, c = r.metrics["py"], r.metrics["c"]
    assert (py.rmse, py.psnr, py.max_err, py.count) == (c.rmse, c.psnr, c.max_err, c.count)
    assert py.texels < 0 and c.texels > 1
    assert r.metrics["bn"].rmse < c.rmse < r.metrics["near"].rmse
    # The metric is the RMS over R, G, B of the masked pixels.
    d = (r.images["c"] - r.truth)[r.mask][:, :3]
    assert abs(np.sqrt(np.mean(d.astype(np.float64) ** 2)) - c.rmse) < 1e-9


def test_compare_errors():
    with pytest.raises(ValueError, match="'oiio-trilinear' is not a libsample filter"):
        ls.compare("oiio-trilinear", size=16, truth=2)
    with pytest.raises(ValueError, match="truth even"):
        ls.compare("trilinear", size=16, truth=3)
    with pytest.raises(ls.LibsampleError, match="no-such-scene"):
        ls.compare("trilinear", scene="no-such-scene", size=16, truth=2)
    with pytest.raises(KeyError, match="bad"):
        ls.compare(lambda q, t: {}["bad"], size=16, truth=2)
