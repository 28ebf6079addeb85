"""libsample: texture filtering and mipmap sampling from numpy.

A thin ctypes layer over libsample's C API (sample.h) and libsample_io's
(sample_io.h); no compiler is needed at import. See doc/python.md.

    import numpy as np, libsample as ls
    tex = ls.Texture(np.random.rand(64, 64, 4).astype(np.float32))
    smp = ls.Sampler(min_filter="linear_mipmap_linear", wrap="repeat")
    rgba = tex.sample(smp, s=[0.5], t=[0.5], dsdx=1 / 16, dtdy=1 / 16)

Texture    a mip-mapped texture (numpy arrays, image files); cube maps
           (Texture.cube), 3D textures (Texture.volume) and lat-long maps
           sampled by 9-float queries (Texture.sample3)
Sampler    sampler state (sample_sampler's fields as keywords)
freq       the frequency response of filters (texsample freq), callables too
compare    error against the ground truth (texsample compare), callables too
LibsampleError, LibsampleArgumentError   errors the C library reports
"""
from . import _lib
from ._errors import LibsampleArgumentError, LibsampleError
from ._handle import ClosedTextureError
from ._names import OPTIONS
from .measure import POINT_DTYPE, CompareMetrics, CompareResult, FreqResult, FreqSummary, compare, freq
from .sampler import Sampler
from .texture import STATS_DTYPE, Samples, Texture, TextureInfo

__all__ = ["Texture", "TextureInfo", "Sampler", "Samples", "STATS_DTYPE", "OPTIONS", "LibsampleError",
           "LibsampleArgumentError", "ClosedTextureError", "freq", "FreqResult", "FreqSummary",
           "compare", "CompareResult", "CompareMetrics",
           "POINT_DTYPE", "names", "isa", "__version__"]


def names(kind):
    """The C names of an enum: kind is "wrap", "filter", "cubic",
    "footprint" or "mipgen" (what Sampler and Texture accept)."""
    from ._names import names as _n
    return _n(kind)


def isa():
    """The instruction set sampling runs on ("scalar", "sse2", "avx2",
    "avx512"); results do not depend on it (sample.h §6)."""
    return _lib.core.sample_isa_name().decode()


__version__ = "0.1.0"
