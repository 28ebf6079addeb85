"""The tools' measurements from Python: the frequency test of ``texsample
freq`` (DESIGN §9, doc/frequency-tests.md) and the comparison against the
ground truth of ``texsample compare`` (DESIGN §8, doc/comparison.md), run by
the same C code through libsample_measure (tools/freq/sample_measure.h), on
libsample's filters or on filters written in Python."""
import os
import ctypes
import dataclasses

import numpy as np

from . import _lib
from ._errors import make_error
from .texture import Texture


class _Filter(ctypes.Structure):
    pass


_FILTER_FN = ctypes.CFUNCTYPE(ctypes.c_int, ctypes.c_void_p, ctypes.c_void_p, ctypes.c_void_p, ctypes.c_size_t,
                              ctypes.c_void_p, ctypes.c_void_p, ctypes.c_size_t)
_Filter._fields_ = [("name", ctypes.c_char_p), ("fn", _FILTER_FN), ("user", ctypes.c_void_p)]


class _Params(ctypes.Structure):
    _fields_ = [("m", ctypes.POINTER(ctypes.c_double)), ("nm", ctypes.c_int),
                ("theta_deg", ctypes.POINTER(ctypes.c_double)), ("ntheta", ctypes.c_int),
                ("r", ctypes.POINTER(ctypes.c_double)), ("nr", ctypes.c_int), ("n", ctypes.c_int),
                ("f_step", ctypes.c_double), ("f_max", ctypes.c_double), ("width", ctypes.c_int),
                ("rows", ctypes.c_int), ("phases", ctypes.c_int)]


# sample_freq_point, field for field.
POINT_DTYPE = np.dtype([("filter", "<i4"), ("im", "<i4"), ("itheta", "<i4"), ("ir", "<i4"), ("p", "<i4"),
                        ("q", "<i4"), ("f", "<f8"), ("F", "<f8"), ("alias_F", "<f8"), ("re", "<f8"),
                        ("im_", "<f8"), ("amp", "<f8"), ("stderr", "<f8"), ("residual", "<f8"),
                        ("texels", "<f8"), ("ns", "<f8")])


class _CompareParams(ctypes.Structure):
    _fields_ = [("scene", ctypes.c_char_p), ("size", ctypes.c_int), ("truth", ctypes.c_int),
                ("threads", ctypes.c_int)]


class _CompareMetrics(ctypes.Structure):
    _fields_ = [(n, ctypes.c_double) for n in ("rmse", "psnr", "max_err", "count", "seconds", "ns_per_sample",
                                               "texels")]


class _Summary(ctypes.Structure):
    _fields_ = [(n, ctypes.c_double) for n in ("pass_", "pass_worst", "alias", "alias_worst", "texels", "ns")] + \
               [("npass", ctypes.c_int), ("nstop", ctypes.c_int)]


_measure = None


def _lib_measure():
    global _measure
    if _measure is None:
        # Its libsample_io dependency, loaded first from where the package
        # finds it, since an installed library carries no search path
        # (libsample.so is loaded already). A build without it has none.
        try:
            _lib.io()
        except ImportError:
            pass
        lib = _lib.load("sample_measure")
        lib.sample_freq_run.restype = ctypes.c_int
        lib.sample_freq_run.argtypes = [ctypes.POINTER(_Params), ctypes.POINTER(_Filter), ctypes.c_int,
                                        ctypes.POINTER(ctypes.c_void_p), ctypes.c_char_p, ctypes.c_size_t]
        lib.sample_freq_count.restype = ctypes.c_size_t
        lib.sample_freq_count.argtypes = [ctypes.c_void_p]
        lib.sample_freq_points.restype = None
        lib.sample_freq_points.argtypes = [ctypes.c_void_p, ctypes.c_void_p]
        lib.sample_freq_summarize.restype = _Summary
        lib.sample_freq_summarize.argtypes = [ctypes.c_void_p, ctypes.c_int, ctypes.c_int, ctypes.c_int]
        lib.sample_freq_free.restype = None
        lib.sample_freq_free.argtypes = [ctypes.c_void_p]
        lib.sample_compare_run.restype = ctypes.c_int
        lib.sample_compare_run.argtypes = [ctypes.POINTER(_CompareParams), ctypes.POINTER(_Filter), ctypes.c_int,
                                           ctypes.POINTER(ctypes.c_void_p), ctypes.c_char_p, ctypes.c_size_t]
        lib.sample_compare_size.restype = None
        lib.sample_compare_size.argtypes = [ctypes.c_void_p, ctypes.POINTER(ctypes.c_int),
                                            ctypes.POINTER(ctypes.c_int)]
        for name in ("truth", "mask", "image"):
            f = getattr(lib, "sample_compare_" + name)
            f.restype = ctypes.c_void_p
            f.argtypes = [ctypes.c_void_p] + ([ctypes.c_int] if name == "image" else [])
        lib.sample_compare_metrics_get.restype = _CompareMetrics
        lib.sample_compare_metrics_get.argtypes = [ctypes.c_void_p, ctypes.c_int]
        lib.sample_compare_free.restype = None
        lib.sample_compare_free.argtypes = [ctypes.c_void_p]
        _measure = lib
    return _measure


@dataclasses.dataclass(frozen=True)
class FreqSummary:
    """texsample freq's numbers for one filter (summary.csv): pass-band
    fidelity (mean |H| for 0 < F < 0.4 cycles/pixel, ideal 1) and aliasing
    (mean leakage for F > 0.6, ideal 0), each with its worst orientation,
    and texels read and nanoseconds per sample."""
    pass_band: float
    pass_worst: float
    aliasing: float
    alias_worst: float
    texels: float
    ns: float


class FreqResult:
    """What ``freq`` measured.

    ``points``: every measured point, a structured array (POINT_DTYPE):
    filter/im/itheta/ir index the filters, m, theta and r lists; p, q the
    grating's wave vector and f its frequency (cycles/texel); F the screen
    frequency f·m (cycles/pixel), alias_F where it aliases to; re, im_ the
    complex response, amp = |H| (response below Nyquist, leakage above),
    stderr its standard error, residual what the fit leaves; texels and ns
    per sample. ``curve(filter, m, theta, r)`` gives one response curve;
    ``summary(filter, m=None, r=None)`` the summary numbers.
    """

    def __init__(self, names, m, theta, r, points, summaries):
        self.filters, self.m, self.theta, self.r = names, m, theta, r
        self.points = points
        self._summaries = summaries

    def _index(self, what, values, v):
        try:
            return values.index(v)
        except ValueError:
            raise KeyError("%s %r was not measured; %s" % (what, v, values)) from None

    def curve(self, filter, m, theta=None, r=None):
        """(F, amp, stderr) of one curve, in increasing F: the filter by name
        or index; m, theta and r by value (theta and r default to the
        first measured)."""
        b = filter if isinstance(filter, int) else self._index("filter", self.filters, filter)
        sel = ((self.points["filter"] == b) & (self.points["im"] == self._index("m", self.m, m))
               & (self.points["itheta"] == self._index("theta", self.theta, self.theta[0] if theta is None else theta))
               & (self.points["ir"] == self._index("r", self.r, self.r[0] if r is None else r)))
        p = self.points[sel]
        return p["F"].copy(), p["amp"].copy(), p["stderr"].copy()

    def summary(self, filter, m=None, r=None):
        """FreqSummary of a filter over every orientation, at one m and r (by
        value) or folded over them (None)."""
        b = filter if isinstance(filter, int) else self._index("filter", self.filters, filter)
        im = -1 if m is None else self._index("m", self.m, m)
        ir = -1 if r is None else self._index("r", self.r, r)
        return self._summaries(b, im, ir)


def _filter_list(filters):
    if isinstance(filters, dict):
        return list(filters.items())
    if isinstance(filters, str) or callable(filters):
        filters = [filters]
    out = []
    for f in filters:
        if isinstance(f, str):
            out.append((f, f))
        elif callable(f):
            out.append((getattr(f, "__name__", "callable"), f))
        else:
            raise TypeError("filters: registry names (str) or callables, not %r" % (f,))
    return out


def freq(filters, m=(1.0, 2.0, 5.7, 16.0), theta=(0.0, 22.5, 45.0), r=(1.0,), n=256, f_step=1 / 32, f_max=2.0,
         width=16, rows=1, phases=64):
    """The frequency response of filters, measured as ``texsample freq``
    measures it (doc/frequency-tests.md): complex gratings of f cycles/texel
    on an n x n REPEAT texture, sampled with m texels per pixel along the
    wave and m·r across it at ``phases`` offsets of a ``width`` x ``rows``
    screen, and the least-squares response at the screen frequency
    F = f·m, up to ``f_max`` in steps of ``f_step`` cycles/pixel.

    ``filters``: one or a list of filters, or a dict {name: filter}. A filter
    is a name of the tools' registry ("nearest", "bilinear", "trilinear",
    "aniso16", "cubic_mipmap_linear", "ewa", ...: doc/comparison.md),
    sampled by libsample, or a Python callable ``f(queries, texture)``:
    queries an (N, 6) float32 array (s, t and the Jacobian), texture the
    grating (a libsample.Texture, 2 channels, float, box pyramid, REPEAT,
    usable during the call only: ``texture.levels`` gives its texels); it
    returns (N, 4) RGBA (channels 0 and 1 are measured). An exception in
    the callable stops the measurement and is raised from here.

    Returns a FreqResult. The GIL is held while a callable runs and
    released while libsample's filters do.
    """
    lib = _lib_measure()
    flist = _filter_list(filters)
    lists = [tuple(float(v) for v in np.atleast_1d(x)) for x in (m, theta, r)]
    arrays = [(ctypes.c_double * len(x))(*x) for x in lists]
    params = _Params(arrays[0], len(lists[0]), arrays[1], len(lists[1]), arrays[2], len(lists[2]), int(n),
                     float(f_step), float(f_max), int(width), int(rows), int(phases))
    res = _run(lib.sample_freq_run, params, flist)
    try:
        pts = np.empty(lib.sample_freq_count(res), POINT_DTYPE)
        lib.sample_freq_points(res, pts.ctypes.data)
        sums = {}
        for b in range(len(flist)):
            for im in range(-1, len(lists[0])):
                for ir in range(-1, len(lists[2])):
                    s = lib.sample_freq_summarize(res, b, im, ir)
                    sums[b, im, ir] = FreqSummary(s.pass_, s.pass_worst, s.alias, s.alias_worst, s.texels, s.ns)
    finally:
        lib.sample_freq_free(res)
    return FreqResult([name for name, _ in flist], list(lists[0]), list(lists[1]), list(lists[2]), pts,
                      lambda b, im, ir: sums[b, im, ir])


def _run(run, params, flist):
    """Call sample_freq_run or sample_compare_run with the filters: registry
    names as they are, callables through ctypes callbacks. Returns the
    result handle; raises what a callable raised, else the C message."""
    failure = []
    cfilters = (_Filter * len(flist))()
    keep = []
    for k, (name, f) in enumerate(flist):
        # A registry filter is looked up by its registry name; a callable's
        # name is its label in C's messages.
        cfilters[k].name = (f if isinstance(f, str) else name).encode()
        if callable(f):
            cb = _FILTER_FN(_callback(f, name, failure))
            keep.append(cb)
            cfilters[k].fn = cb
    res = ctypes.c_void_p()
    err = ctypes.create_string_buffer(512)
    if run(ctypes.byref(params), cfilters, len(flist), ctypes.byref(res), err, len(err)) != 0:
        if failure:
            raise failure[0]
        raise make_error(1, err.value.decode(errors="replace"))
    return res


@dataclasses.dataclass(frozen=True)
class CompareMetrics:
    """One filter's row of texsample compare's results.csv: RMSE, PSNR (dB,
    peak 1) and the largest per-pixel error over R, G, B of the measured
    pixels (linear), their count, and the time and texels per query
    (texels < 0: not counted, as for callables)."""
    rmse: float
    psnr: float
    max_err: float
    count: int
    seconds: float
    ns_per_sample: float
    texels: float


@dataclasses.dataclass(frozen=True)
class CompareResult:
    """What ``compare`` measured: the filter names; the ground truth
    (h, w, 4) linear RGBA; the metric mask (h, w) bool (True: the pixel is
    measured); each filter's picture and CompareMetrics, by name."""
    filters: list
    truth: np.ndarray
    mask: np.ndarray
    images: dict
    metrics: dict


def compare(filters, scene="plane", size=64, truth=8, threads=None):
    """Render a scene of ``texsample compare`` (doc/comparison.md: "plane",
    "teapot", "teapot-image", "zoneplate", "zoneplate-oblique",
    "photo-plane", or a scene file) with each filter and measure it against
    the ground truth (DESIGN §8: ``truth`` x ``truth`` samples of the exact
    texture over each pixel's 2 x 2-pixel footprint), as texsample compare
    does, ``size`` x ``size`` pixels.

    ``filters`` as for ``freq``: registry names (corner-mode entries such as
    "blinn-newell-corners" too) or callables ``f(queries, texture)``, here
    given each row's pixels that show one texture of the scene (the
    scene's texture, usable during the call). ``threads`` (default: every
    processor) serve the view, the truth and registry filters; callables
    run on one thread. Returns a CompareResult.
    """
    lib = _lib_measure()
    flist = _filter_list(filters)
    params = _CompareParams(os.fsencode(scene), int(size), int(truth),
                            int(threads) if threads else (os.cpu_count() or 1))
    res = _run(lib.sample_compare_run, params, flist)
    try:
        w, h = ctypes.c_int(), ctypes.c_int()
        lib.sample_compare_size(res, ctypes.byref(w), ctypes.byref(h))
        shape = (h.value, w.value, 4)

        def floats(ptr):
            return np.ctypeslib.as_array(ctypes.cast(ptr, ctypes.POINTER(ctypes.c_float)), shape).copy()

        mask = np.ctypeslib.as_array(ctypes.cast(lib.sample_compare_mask(res), ctypes.POINTER(ctypes.c_ubyte)),
                                     shape[:2]).astype(bool)
        images, metrics = {}, {}
        for k, (name, _) in enumerate(flist):
            images[name] = floats(lib.sample_compare_image(res, k))
            m = lib.sample_compare_metrics_get(res, k)
            metrics[name] = CompareMetrics(m.rmse, m.psnr, m.max_err, int(m.count), m.seconds, m.ns_per_sample,
                                           m.texels)
        return CompareResult([name for name, _ in flist], floats(lib.sample_compare_truth(res)), mask, images,
                             metrics)
    finally:
        lib.sample_compare_free(res)


def _callback(f, name, failure):
    def call(user, tex, queries, count, rgba, err, errlen):
        t = Texture._wrap(tex, owned=False)
        try:
            q = np.ctypeslib.as_array(ctypes.cast(queries, ctypes.POINTER(ctypes.c_float)), (count, 6)).copy()
            out = np.asarray(f(q, t))
            if out.shape != (count, 4) or out.dtype.kind not in "fiu":
                raise ValueError("filter %s returned %s %s for %d queries; (N, 4) real numbers expected"
                                 % (name, out.dtype, out.shape, count))
            np.ctypeslib.as_array(ctypes.cast(rgba, ctypes.POINTER(ctypes.c_float)), (count, 4))[:] = out
            return 0
        except BaseException as e:  # noqa: B902 — carried across C and raised by freq()
            failure.append(e)
            msg = ("filter %s raised %s" % (name, type(e).__name__)).encode()[: errlen - 1]
            ctypes.memmove(err, msg + b"\0", len(msg) + 1)
            return 1
        finally:
            t.close()
    return call
