"""Enum values from their C names (sample_*_parse, sample_*_name) or ints."""
from . import _lib


def _count(kind):
    """SAMPLE_<KIND>_COUNT, read from the library: sample_*_name gives
    "unknown" past the last value (names.c)."""
    f = getattr(_lib.core, "sample_%s_name" % kind)
    n = 0
    while f(n) != b"unknown":
        n += 1
    return n


_COUNTS = {k: _count(k) for k in ("wrap", "filter", "cubic", "footprint", "ewa_kernel", "mipgen", "format",
                                   "texture_kind")}

# The SAMPLE_OPT_* bits (sample.h), by the command line's option names.
OPTIONS = {
    "legacy_switchover": 1 << 0,
    "nearest_level_floor": 1 << 1,
    "cubic_clamp": 1 << 2,
    "aniso_pow2": 1 << 3,
    "bn_area_weight": 1 << 5,
    "ewa_clamp": 1 << 6,
}


def names(kind):
    """Every name of enum `kind` ("wrap", "filter", ...), in value order."""
    f = getattr(_lib.core, "sample_%s_name" % kind)
    return [f(i).decode() for i in range(_COUNTS[kind])]


def parse(kind, value, field):
    """The int value of `value` (a C name as sample_<kind>_parse reads it, or
    an int in range) for the keyword `field`; ValueError otherwise."""
    if isinstance(value, str):
        v = getattr(_lib.core, "sample_%s_parse" % kind)(value.encode())
        if v < 0:
            raise ValueError("%s: unknown %s %r; one of: %s" % (field, kind, value, ", ".join(names(kind))))
        return v
    if isinstance(value, bool) or not isinstance(value, int) and not hasattr(value, "__index__"):
        raise TypeError("%s: a %s name (str) or int, not %r" % (field, kind, value))
    v = int(value)
    if not 0 <= v < _COUNTS[kind]:
        raise ValueError("%s: %d is not a %s (0 to %d)" % (field, v, kind, _COUNTS[kind] - 1))
    return v


def name(kind, value):
    return getattr(_lib.core, "sample_%s_name" % kind)(value).decode()


def parse_options(value):
    """SAMPLE_OPT_* bits from an int or an iterable of OPTIONS names."""
    if isinstance(value, int) and not isinstance(value, bool):
        if value < 0 or value >= 1 << 32:
            raise ValueError("options: %d is not an unsigned 32-bit mask" % value)
        return value
    if isinstance(value, str):
        value = [value]
    bits = 0
    for o in value:
        if o not in OPTIONS:
            raise ValueError("options: unknown option %r; one of: %s" % (o, ", ".join(OPTIONS)))
        bits |= OPTIONS[o]
    return bits
