"""Textures: numpy arrays or image files in, sampled values out."""
import ctypes
import dataclasses
import os

import numpy as np

from . import _arrays, _errors, _lib, _names
from ._arrays import STATS_DTYPE, Samples
from ._handle import Handle
from .sampler import as_sampler
from .texture3 import CubeVolume

__all__ = ["Texture", "TextureInfo", "Samples", "STATS_DTYPE"]


@dataclasses.dataclass(frozen=True)
class TextureInfo:
    """What a texture holds (sample_texture_info)."""
    width: int
    height: int
    channels: int
    levels: int
    format: str   # "float", "half", "unorm8", "srgb8"
    bytes: int    # texel memory of every level
    kind: str     # "2d", "cube", "3d"
    depth: int = 1  # layers of level 0: a 3D texture's slices, a cube map's 6 faces, else 1


class Texture(CubeVolume):
    """An immutable, mip-mapped texture (sample_texture).

    ``Texture(array, format=None, srgb=False, mip="box", wrap="clamp_to_edge",
    max_levels=0)`` copies ``array`` (H x W, or H x W x C with C = 1 to 4;
    row 0 is t = 0) into a new texture; the array may be changed or freed
    afterwards. Storage follows the dtype: float32 -> "float", float16 ->
    "half", uint8 -> "unorm8" (value/255) or, with ``srgb=True``, "srgb8"
    (sRGB-encoded colour, linear alpha); float64 is stored as float32.
    ``format`` names the storage explicitly (a float array is converted to
    "half"). ``mip`` is how the pyramid is built: "box", "lanczos3",
    "kaiser", or "none"/None for the base level only; ``wrap`` (one name or
    an (s, t) pair) is how its kernels read past the edges; ``max_levels``
    caps the level count (0: down to 1 x 1).

    ``Texture.load(path, ...)`` reads an image file through libsample_io,
    ``Texture.from_levels(arrays)`` takes the levels as given.
    ``Texture.cube(faces)`` and ``Texture.volume(array)`` make cube maps and
    3D textures, sampled with ``sample3``; ``sample3(..., latlong=True)``
    reads a 2D texture as a lat-long environment map (doc/python.md).

    The texture owns its C object: ``close()`` (or a ``with`` block) frees
    it, after which every use raises ValueError; it is freed as well when
    the object is garbage-collected. Sampling releases the GIL and may run
    from several threads at once.
    """

    def __init__(self, array, format=None, srgb=False, mip="box", wrap="clamp_to_edge", max_levels=0):
        img, keep = _arrays.image(array, format, srgb)
        params = _arrays.mip_params(mip, wrap, max_levels)
        self._handle = Handle(self._create(lambda out, err: _lib.core.sample_texture_create(
            ctypes.byref(img), ctypes.byref(params), out, err), "sample_texture_create"))
        del keep

    @staticmethod
    def _create(fn, what):
        out = ctypes.c_void_p()
        err = _lib.Error()
        _errors.check(fn(ctypes.byref(out), ctypes.byref(err)), err, what)
        return out.value

    @classmethod
    def _wrap(cls, ptr, owned):
        t = cls.__new__(cls)
        t._handle = Handle(ptr, owned)
        return t

    @classmethod
    def from_levels(cls, levels, format=None, srgb=False):
        """A texture from its levels as given (sample_texture_create_levels):
        level k must be max(1, W >> k) x max(1, H >> k) with the base's
        channels and dtype; a partial chain is allowed."""
        return cls._create_from_levels("from_levels", levels, _lib.Image, 1,
                                       lambda lv, what: _arrays.as_level(_arrays.image(lv, format, srgb, what)),
                                       _lib.core.sample_texture_create_levels)

    @classmethod
    def load(cls, path, colorspace=None, ocio_config=None, mip="box", wrap="clamp_to_edge", max_levels=0,
             use_file_levels=True, float_storage=False, premultiply=False, max_bytes=0):
        """Read an image file (any format OpenImageIO reads; mip-mapped .exr
        and .tx files give their stored levels unless use_file_levels is
        False) through libsample_io, converting colour to the OCIO config's
        scene-linear space (sample_io.h, doc/io-and-colour.md). A file
        without levels gets a pyramid built with ``mip`` and ``wrap``.
        Raises LibsampleError with libsample_io's message on failure, and
        ImportError when libsample_io is not built."""
        io = _lib.io()
        o = _lib.IoOptions()
        io.sample_io_options_init(ctypes.byref(o))
        o.colorspace = None if colorspace is None else colorspace.encode()
        o.ocio_config = None if ocio_config is None else os.fsencode(ocio_config)
        o.use_file_levels = int(bool(use_file_levels))
        o.float_storage = int(bool(float_storage))
        o.premultiply = int(bool(premultiply))
        o.max_bytes = int(max_bytes)
        params = _arrays.mip_params(mip, wrap, max_levels)
        p = os.fsencode(path)
        return cls._wrap(cls._create(lambda out, err: io.sample_io_read_texture(
            p, ctypes.byref(o), ctypes.byref(params), out, err), "sample_io_read_texture"), True)

    # ---- lifetime ----------------------------------------------------------

    def close(self):
        """Free the C texture (idempotent). Later uses raise ValueError."""
        h = getattr(self, "_handle", None)
        if h is not None:
            h.close()

    @property
    def closed(self):
        return self._handle.closed

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def __del__(self):
        if _lib is not None and _lib.core is not None:
            self.close()

    def __repr__(self):
        if self.closed:
            return "<libsample.Texture (closed)>"
        i = self.info
        size = "%dx%d" % (i.width, i.height) + ("x%d" % i.depth if i.kind == "3d" else "")
        return "<libsample.Texture %s %s x%d %s, %d levels>" % (i.kind, size, i.channels, i.format, i.levels)

    # ---- what it holds -----------------------------------------------------

    @property
    def info(self):
        """TextureInfo: size, channels, level count, format, bytes, kind,
        depth (layers of level 0, as sample_texture_info gives it: a 3D
        texture's slices, a cube map's 6 faces, 1 for a 2D texture)."""
        c = _lib.TextureInfo()
        with self._handle as p:
            _lib.core.sample_texture_info_get(p, ctypes.byref(c))
        return TextureInfo(c.width, c.height, c.channels, c.levels, _names.name("format", c.format),
                           c.bytes, _names.name("texture_kind", c.kind), c.depth)

    @property
    def kind(self):
        """"2d", "cube" or "3d" (info.kind; a texture never changes kind)."""
        k = getattr(self, "_kind", None)
        if k is None:
            k = self._kind = self.info.kind
        return k

    def level_size(self, level):
        """(width, height) of a level, of every kind: a cube map's face is
        width x height, a 3D texture's slice too (level_size3 adds the
        third size)."""
        return self.level_size3(level)[:2]

    def level_size3(self, level):
        """(width, height, layers) of a level (sample_texture_level_size3):
        layers is the depth of a 3D texture's level, 6 for a cube map (its
        faces), 1 for a 2D texture."""
        w, h, d = ctypes.c_int(), ctypes.c_int(), ctypes.c_int()
        with self._handle as p:
            if not _lib.core.sample_texture_level_size3(p, int(level), ctypes.byref(w), ctypes.byref(h),
                                                        ctypes.byref(d)):
                raise IndexError("level %d: the texture has %d levels" % (level, self.info.levels))
        return w.value, h.value, d.value

    def texel(self, level, i, j, layer=0):
        """Texel (i, j) of a level, decoded to linear RGBA float32
        (sample_texture_texel_layer): column i, row j (row 0 is t = 0) of
        layer ``layer`` — a cube map's face (0 to 5: +X, -X, +Y, -Y, +Z, -Z),
        a 3D texture's slice (0 is r = 0), 0 for a 2D texture."""
        w, h, d = self.level_size3(level)
        if not (0 <= i < w and 0 <= j < h and 0 <= layer < d):
            raise IndexError("texel (%d, %d) of layer %d outside level %d's %d x %d x %d"
                             % (i, j, layer, level, w, h, d))
        out = np.empty(4, np.float32)
        with self._handle as p:
            _lib.core.sample_texture_texel_layer(p, int(level), int(layer), int(i), int(j),
                                                 out.ctypes.data_as(_lib.c_float_p))
        return out

    def level(self, k):
        """Level k decoded to linear RGBA float32, row 0 at t = 0: shape
        (h, w, 4) for a 2D texture, (6, n, n, 4) for a cube map (faces in
        OpenGL's order), (d, h, w, 4) for a 3D texture (slice 0 at r = 0
        first). The values sample_texture_texel_layer gives (1 channel reads
        as (r, 0, 0, 1), 2 as (r, g, 0, 1), 3 as (r, g, b, 1); sRGB
        decoded). A new array; the texture is not changed through it."""
        if self.kind != "2d":
            return self._level_layers(k)
        w, h = self.level_size(k)
        jj, ii = np.meshgrid(np.arange(h, dtype=np.float64), np.arange(w, dtype=np.float64), indexing="ij")
        q = np.zeros((h * w, 6), np.float32)
        q[:, 0] = ((ii.ravel() + 0.5) / w)
        q[:, 1] = ((jj.ravel() + 0.5) / h)
        return self.sample(self._level_sampler(k), q).reshape(h, w, 4)

    @property
    def levels(self):
        """Every level as Texture.level(k) gives it: a list of float32
        arrays, decoded linear RGBA."""
        return [self.level(k) for k in range(self.info.levels)]

    # ---- sampling ----------------------------------------------------------

    def sample(self, sampler, queries=None, *, s=None, t=None, dsdx=0.0, dtdx=0.0, dsdy=0.0, dtdy=0.0,
               corners=None, bias=None, derivatives=False, stats=False, out=None):
        """Sample N queries with one sampler state (sample_batch).

        ``queries``: an (N, 6) array of (s, t, ds/dx, dt/dx, ds/dy, dt/dy),
        the order of ``texsample lookup``'s query file; or give ``s``, ``t``
        and optionally the Jacobian entries as arrays (or scalars,
        broadcast). A C-contiguous float32 array is passed to C as it is
        (no copy); anything else real-valued is copied to float32.
        ``corners``: (N, 8) or (N, 4, 2) footprint corners (Blinn–Newell's
        corner mode); ``bias``: (N,) per-query LOD bias. ``sampler``: a
        Sampler, or a dict of its keywords.

        Returns the (N, 4) float32 linear RGBA results (into ``out`` when
        given); with ``derivatives=True`` or ``stats=True`` a Samples tuple
        (rgba, drgba_ds, drgba_dt, stats). A query whose coordinates or
        Jacobian hold NaN or inf returns the border colour (DESIGN §10).
        """
        sampler = as_sampler(sampler)
        if self.kind != "2d":
            raise TypeError("sample: a %s texture takes 9-float queries (direction or (s, t, r)): use sample3"
                            % self.kind)
        q = self._queries(queries, s, t, dsdx, dtdx, dsdy, dtdy)
        n = q.shape[0]
        c = None
        if corners is not None:
            c = np.asarray(corners)
            c = _arrays.float_array(c.reshape(c.shape[0], 8) if c.ndim == 3 and c.shape[1:] == (4, 2) else c,
                             "corners", (8,), n)
        b = None if bias is None else _arrays.float_array(bias, "bias", (), n)
        rgba = _arrays.out_array(out, "out", n)
        ds = np.empty((n, 4), np.float32) if derivatives else None
        dt = np.empty((n, 4), np.float32) if derivatives else None
        st = np.empty(n, STATS_DTYPE) if stats else None
        args = _lib.BatchArgs(count=n, queries=_arrays.ptr(q), corners=_arrays.ptr(c), lod_bias=_arrays.ptr(b), rgba=_arrays.ptr(rgba),
                              drgba_ds=_arrays.ptr(ds), drgba_dt=_arrays.ptr(dt), stats=_arrays.ptr(st))
        if n:
            with self._handle as p:
                status = _lib.core.sample_batch(p, ctypes.byref(sampler._state), ctypes.byref(args))
            _errors.check(status, None, "sample_batch")
        if derivatives or stats:
            return Samples(rgba, ds, dt, st)
        return rgba

    @staticmethod
    def _queries(queries, s, t, dsdx, dtdx, dsdy, dtdy):
        if queries is not None:
            if s is not None or t is not None:
                raise TypeError("sample: give queries or s=, t=, not both")
            return _arrays.float_array(queries, "queries", (6,))
        if s is None or t is None:
            raise TypeError("sample: give queries (N x 6) or s= and t=")
        cols = [np.asarray(v) for v in (s, t, dsdx, dtdx, dsdy, dtdy)]
        for name, v in zip(("s", "t", "dsdx", "dtdx", "dsdy", "dtdy"), cols):
            if v.dtype.kind not in "fiu":
                raise TypeError("%s: real numbers, not dtype %s" % (name, v.dtype))
            if v.ndim > 1:
                raise ValueError("%s: a 1-D array or a scalar, not shape %s" % (name, v.shape))
        try:
            n = np.broadcast(*cols).size
            q = np.empty((n, 6), np.float32)
            for k, v in enumerate(cols):
                q[:, k] = np.broadcast_to(v, (n,))
        except ValueError:
            raise ValueError("s, t, dsdx, ...: arrays of one length N (or scalars), not %s"
                             % [v.shape for v in cols]) from None
        return q
