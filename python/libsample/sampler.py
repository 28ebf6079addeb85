"""Sampler state: an OpenGL sampler object (sample.h's sample_sampler)."""
import ctypes
import math

from . import _lib, _names
from ._errors import LibsampleArgumentError

# Keyword -> the enum its values name (sample_<kind>_parse).
_ENUM_FIELDS = {"wrap_s": "wrap", "wrap_t": "wrap", "wrap_r": "wrap", "min_filter": "filter",
                "mag_filter": "filter", "footprint": "footprint", "cubic": "cubic",
                "ewa_kernel": "ewa_kernel"}
_FLOAT_FIELDS = ("lod_bias", "min_lod", "max_lod", "max_anisotropy", "max_lod_bias")
_INT_FIELDS = ("base_level", "max_level")
FIELDS = tuple(f for f, _ in _lib.SamplerState._fields_)


class Sampler:
    """Sampler state, as ``sample_sampler`` in sample.h (an OpenGL sampler
    object plus libsample's footprint filters).

    Keyword arguments are the C struct's fields; unset ones keep OpenGL's
    initial state (``sample_sampler_init``: REPEAT, min NEAREST_MIPMAP_LINEAR,
    mag LINEAR, LOD range −1000 … 1000, max anisotropy 1):

    - ``wrap_s``, ``wrap_t``, ``wrap_r``: a wrap name ("repeat",
      "clamp_to_edge", "mirrored_repeat", "clamp_to_border", ...) or int;
      ``wrap`` sets all three;
    - ``min_filter``, ``mag_filter``: "nearest", "linear",
      "linear_mipmap_linear", "cubic_mipmap_linear", ... or int;
    - ``footprint``: "none", "aniso", "blinn-newell", "ewa", "feline";
    - ``cubic``: "catmull-rom", "bspline", "mitchell";
    - ``ewa_kernel``: EWA's radial weight, "gaussian", "lanczos2",
      "lanczos3", "mitchell";
    - ``border_color``: 4 floats (linear RGBA);
    - ``lod_bias``, ``min_lod``, ``max_lod``, ``max_anisotropy``,
      ``max_lod_bias``: floats; ``base_level``, ``max_level``: ints;
    - ``options``: an int of SAMPLE_OPT_* bits or names from
      ``libsample.OPTIONS`` ("cubic_clamp", "aniso_pow2", ...).

    The state is checked at construction: an unknown name, a NaN, or a
    state ``sample_sampler_validate`` rejects (max_anisotropy < 1, min_lod >
    max_lod, max_level < base_level, a non-finite lod_bias, ...) raises a
    ValueError (LibsampleArgumentError for the latter) naming the values.
    Attributes read back as set (enums as their C names); a Sampler is
    immutable, ``replace(**kw)`` gives a modified copy.
    """

    __slots__ = ("_state", "_kw")

    def __init__(self, **kw):
        st = _lib.SamplerState()
        _lib.core.sample_sampler_init(ctypes.byref(st))
        if "wrap" in kw:
            w = kw.pop("wrap")
            for f in ("wrap_s", "wrap_t", "wrap_r"):
                kw.setdefault(f, w)
        for key, value in kw.items():
            if key in _ENUM_FIELDS:
                setattr(st, key, _names.parse(_ENUM_FIELDS[key], value, key))
            elif key in _FLOAT_FIELDS:
                setattr(st, key, _float(key, value))
            elif key in _INT_FIELDS:
                if isinstance(value, float) or not hasattr(value, "__index__"):
                    raise TypeError("%s: an int, not %r" % (key, value))
                setattr(st, key, int(value))
            elif key == "border_color":
                c = [_float(key, v) for v in value]
                if len(c) != 4:
                    raise ValueError("border_color: 4 floats (linear RGBA), not %d" % len(c))
                st.border_color[:] = c
            elif key == "options":
                st.options = _names.parse_options(value)
            else:
                raise TypeError("Sampler: unknown keyword %r; the fields are %s and wrap" % (key, ", ".join(FIELDS)))
        if _lib.core.sample_sampler_validate(ctypes.byref(st)) != 0:
            raise LibsampleArgumentError(1, "sample_sampler_validate rejects this state: %s" % self._describe(st))
        self._state = st
        self._kw = kw

    @staticmethod
    def _describe(st):
        return ", ".join("%s=%r" % (f, _field(st, f)) for f in FIELDS)

    def __getattr__(self, key):
        if key in FIELDS:
            return _field(self._state, key)
        raise AttributeError(key)

    def replace(self, **kw):
        """A copy with some fields changed."""
        d = dict(self._kw)
        if "wrap" in kw:
            for f in ("wrap_s", "wrap_t", "wrap_r"):
                d.pop(f, None)
        d.update(kw)
        return Sampler(**d)

    def as_dict(self):
        """Every field, enums as their C names."""
        return {f: _field(self._state, f) for f in FIELDS}

    def __repr__(self):
        return "Sampler(%s)" % ", ".join("%s=%r" % kv for kv in self._kw.items())

    def __eq__(self, other):
        return isinstance(other, Sampler) and self.as_dict() == other.as_dict()

    __hash__ = None


def _float(key, value):
    try:
        v = float(value)
    except (TypeError, ValueError):
        raise TypeError("%s: a float, not %r" % (key, value)) from None
    if math.isnan(v):
        raise ValueError("%s is NaN" % key)
    return v


def _field(st, f):
    v = getattr(st, f)
    if f in _ENUM_FIELDS:
        return _names.name(_ENUM_FIELDS[f], v)
    if f == "border_color":
        return tuple(v)
    return v


def as_sampler(x):
    """x as a Sampler: a Sampler as it is, a dict as its keywords."""
    if isinstance(x, dict):
        return Sampler(**x)
    if not isinstance(x, Sampler):
        raise TypeError("sampler: a libsample.Sampler (or a dict of its keywords), not %r" % type(x).__name__)
    return x
