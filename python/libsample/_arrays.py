"""numpy arrays to the C structs that describe texels and queries
(sample_image, sample_volume, sample_mip_params), and the checks on the
arrays a batch reads and writes."""
import collections
import ctypes

import numpy as np

from . import _lib, _names

# sample_stats (sample.h), field for field.
STATS_DTYPE = np.dtype([("texels", "<u4"), ("level0", "<i2"), ("level1", "<i2"),
                        ("level_frac", "<f4"), ("lod", "<f4")])
assert STATS_DTYPE.itemsize == 16

Samples = collections.namedtuple("Samples", "rgba drgba_ds drgba_dt stats")
Samples.__doc__ = """What Texture.sample and Texture.sample3 return when derivatives or
stats are asked for: rgba (N, 4) float32; drgba_ds, drgba_dt (N, 4) float32
or None (sample3 has none); stats (N,) of STATS_DTYPE or None."""

# Formats by their sample_format_name, and the numpy dtype of each.
FORMATS = {_names.name("format", i): i for i in range(_names._COUNTS["format"])}
_FORMAT_DTYPE = {"float": np.float32, "half": np.float16, "unorm8": np.uint8, "srgb8": np.uint8}


def format_of(a, format, srgb):
    """The storage format of texels `a`: `format` when named, else by dtype."""
    if format is not None:
        if format not in FORMATS:
            raise ValueError("format: %r is not one of %s" % (format, ", ".join(FORMATS)))
        if srgb and format != "srgb8":
            raise ValueError("srgb=True is format 'srgb8', not %r" % format)
        return format
    kind = a.dtype
    if kind == np.uint8:
        return "srgb8" if srgb else "unorm8"
    if srgb:
        raise ValueError("srgb=True needs uint8 texels, not %s (float texels are linear)" % kind)
    if kind == np.float16:
        return "half"
    if kind in (np.float32, np.float64):
        return "float"
    raise TypeError("texels: float32, float16 or uint8 (float64 is stored as float32), not %s" % kind)


def _texels(array, format, srgb, what, ndim, shape_text):
    """`array` with a channel axis, as a C-contiguous array of its storage
    dtype (the same memory when it already is one), and its format."""
    a = np.asarray(array)
    if a.ndim == ndim - 1:
        a = a[..., np.newaxis]
    if a.ndim != ndim or not 1 <= a.shape[-1] <= 4:
        raise ValueError("%s: %s with C = 1 to 4, not shape %s" % (what, shape_text, a.shape))
    fmt = format_of(a, format, srgb)
    want = _FORMAT_DTYPE[fmt]
    if a.dtype != want and (want == np.uint8 or a.dtype.kind != "f"):
        raise TypeError("%s: format %r stores %s; the array is %s" % (what, fmt, np.dtype(want).name, a.dtype))
    return np.ascontiguousarray(a, dtype=want), fmt


def image(array, format=None, srgb=False, what="texels"):
    """A sample_image over a C-contiguous copy (or view) of `array` (H x W
    or H x W x C); returns (image, the array it points into, which must
    outlive the C call)."""
    a, fmt = _texels(array, format, srgb, what, 3, "an H x W or H x W x C array")
    img = _lib.Image(width=a.shape[1], height=a.shape[0], channels=a.shape[2],
                     format=FORMATS[fmt], data=a.ctypes.data, row_stride=0)
    return img, a


def volume(array, format=None, srgb=False, what="texels"):
    """A sample_volume over `array` (D x H x W or D x H x W x C, slice 0 at
    r = 0 first); returns (volume, the array it points into)."""
    a, fmt = _texels(array, format, srgb, what, 4, "a D x H x W or D x H x W x C array")
    vol = _lib.Volume(width=a.shape[2], height=a.shape[1], depth=a.shape[0], channels=a.shape[3],
                      format=FORMATS[fmt], data=a.ctypes.data, row_stride=0, slice_stride=0)
    return vol, a


def as_level(described):
    """The (struct, array) that image() or volume() gives as the ([struct],
    [array]) of a level of one struct (faces() gives six)."""
    return [described[0]], [described[1]]


def faces(faces, format=None, srgb=False, what="faces"):
    """The six sample_images of a cube map's level: `faces` a (6, N, N[, C])
    array or a sequence of six (N, N[, C]) arrays in OpenGL's order +X, -X,
    +Y, -Y, +Z, -Z. Returns (images, the arrays they point into)."""
    if isinstance(faces, np.ndarray) or not hasattr(faces, "__len__"):
        faces = np.asarray(faces)
        if faces.ndim not in (3, 4):
            raise ValueError("%s: a (6, N, N) or (6, N, N, C) array or six (N, N[, C]) arrays, not shape %s"
                             % (what, faces.shape))
    if len(faces) != 6:
        raise ValueError("%s: six faces (+X, -X, +Y, -Y, +Z, -Z), not %d" % (what, len(faces)))
    imgs = (_lib.Image * 6)()
    keep = []
    for f in range(6):
        imgs[f], a = image(faces[f], format, srgb, "%s[%d]" % (what, f))
        keep.append(a)
    return imgs, keep


def mip_params(mip, wrap, max_levels, axes=("s", "t")):
    """sample_mip_params: `wrap` one wrap name (or int) for every axis, or
    one per axis of `axes`; unnamed axes keep sample_mip_params_init's."""
    p = _lib.MipParams()
    _lib.core.sample_mip_params_init(ctypes.byref(p))
    p.filter = 0 if mip is None else _names.parse("mipgen", mip, "mip")
    if isinstance(wrap, (str, int)):
        wrap = (wrap,) * len(axes)
    wrap = tuple(wrap)
    if len(wrap) != len(axes):
        raise ValueError("wrap: one wrap mode or %d, (%s), not %r" % (len(axes), ", ".join(axes), wrap))
    for axis, w in zip(axes, wrap):
        setattr(p, "wrap_" + axis, _names.parse("wrap", w, "wrap"))
    if int(max_levels) < 0:
        raise ValueError("max_levels: 0 (all) or more, not %d" % max_levels)
    p.max_levels = int(max_levels)
    return p


def float_array(x, name, shape_tail, n=None):
    """x as a C-contiguous float32 array of shape (N,) + shape_tail: the
    same memory when it already is one (zero-copy), else a copy."""
    a = np.asarray(x)
    if a.dtype.kind not in "fiu":
        raise TypeError("%s: a float32 array (or real numbers), not dtype %s" % (name, a.dtype))
    want = (n if n is not None else (a.shape[0] if a.ndim else -1),) + shape_tail
    if a.shape != want:
        spelled = " x ".join("N" if i == 0 and n is None else str(d) for i, d in enumerate(want))
        raise ValueError("%s: shape (%s) expected, not %s" % (name, spelled, a.shape))
    return np.ascontiguousarray(a, dtype=np.float32)


def out_array(x, name, n):
    if x is None:
        return np.empty((n, 4), np.float32)
    if not (isinstance(x, np.ndarray) and x.dtype == np.float32 and x.shape == (n, 4)
            and x.flags.c_contiguous and x.flags.writeable):
        raise ValueError("%s: a writable C-contiguous float32 array of shape (%d, 4)" % (name, n))
    return x


def ptr(a):
    return None if a is None else a.ctypes.data
