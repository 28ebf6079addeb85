"""Cube maps, 3D textures and lat-long maps: the textures sampled by
9-float queries (sample_query3: p, dp/dx, dp/dy, GLSL textureGrad's order).

Texture inherits these methods; they live here to keep the 2D texture's
module readable. The C side is doc/environment-maps.md (cube maps,
lat-long maps) and doc/volumes.md (3D textures).
"""
import ctypes

import numpy as np

from . import _arrays, _errors, _lib
from .sampler import Sampler, as_sampler

# The frame of each cube face (GL 4.6 table 8.19), in OpenGL's face order
# +X, -X, +Y, -Y, +Z, -Z: the major axis and the directions U, V with
# sc = R.U, tc = R.V, so that the direction axis + sc*U + tc*V lies on that
# face at face coordinates (sc, tc) in [-1, 1] (s = (sc + 1)/2, t likewise).
_CUBE_FRAMES = np.array([
    [[1, 0, 0], [0, 0, -1], [0, -1, 0]],    # +X: sc = -rz, tc = -ry
    [[-1, 0, 0], [0, 0, 1], [0, -1, 0]],    # -X: sc = +rz, tc = -ry
    [[0, 1, 0], [1, 0, 0], [0, 0, 1]],      # +Y: sc = +rx, tc = +rz
    [[0, -1, 0], [1, 0, 0], [0, 0, -1]],    # -Y: sc = +rx, tc = -rz
    [[0, 0, 1], [1, 0, 0], [0, -1, 0]],     # +Z: sc = +rx, tc = -ry
    [[0, 0, -1], [-1, 0, 0], [0, -1, 0]],   # -Z: sc = -rx, tc = -ry
], np.float64)


def _queries9(queries, p, dpdx, dpdy):
    """The (N, 9) float32 queries: `queries` as (N, 9) or (N, 3, 3) (rows p,
    dp/dx, dp/dy), zero-copy when C-contiguous float32; or p, dpdx, dpdy as
    (N, 3) arrays or 3-vectors (the derivatives also 0), broadcast."""
    if queries is not None:
        if p is not None:
            raise TypeError("sample3: give queries or p=, not both")
        a = np.asarray(queries)
        if a.ndim == 3 and a.shape[1:] == (3, 3):
            a = a.reshape(a.shape[0], 9)
        return _arrays.float_array(a, "queries", (9,))
    if p is None:
        raise TypeError("sample3: give queries (N x 9) or p= (N x 3)")
    cols = []
    for name, v in (("p", p), ("dpdx", dpdx), ("dpdy", dpdy)):
        a = np.asarray(v)
        if a.dtype.kind not in "fiu":
            raise TypeError("%s: real numbers, not dtype %s" % (name, a.dtype))
        if not (a.ndim in (1, 2) and a.shape[-1] == 3 or a.ndim == 0 and name != "p"):
            raise ValueError("%s: an N x 3 array or a 3-vector%s, not shape %s"
                             % (name, "" if name == "p" else " (or a scalar)", a.shape))
        cols.append(a)
    try:
        shape = np.broadcast(*cols).shape
    except ValueError:
        raise ValueError("p, dpdx, dpdy: N x 3 arrays of one N (or 3-vectors), not %s"
                         % [a.shape for a in cols]) from None
    n = shape[0] if len(shape) == 2 else 1
    q = np.empty((n, 9), np.float32)
    for k, a in enumerate(cols):
        q[:, 3 * k:3 * k + 3] = np.broadcast_to(a, (n, 3))
    return q


class CubeVolume:
    """Texture's constructors and sampling for cube maps, 3D textures and
    lat-long maps (see Texture)."""

    # ---- creation ----------------------------------------------------------

    @classmethod
    def cube(cls, faces, format=None, srgb=False, mip="box", max_levels=0):
        """A cube map (sample_texture_create_cube) from its six faces in
        OpenGL's order +X, -X, +Y, -Y, +Z, -Z: a (6, N, N) or (6, N, N, C)
        array, or a sequence of six (N, N) or (N, N, C) arrays, each with
        row 0 at t = 0 as glTexImage2D takes a face. dtype and ``format``,
        ``srgb`` as for Texture(). The pyramid (``mip``, ``max_levels`` as
        for Texture()) is built face by face, its kernels reading across
        face edges from the adjacent faces; there are no wrap modes.
        Sampled by direction with sample3."""
        imgs, keep = _arrays.faces(faces, format, srgb)
        params = _arrays.mip_params(mip, (), max_levels, axes=())
        return cls._wrap(cls._create(lambda out, err: _lib.core.sample_texture_create_cube(
            imgs, ctypes.byref(params), out, err), "sample_texture_create_cube"), True)

    @classmethod
    def cube_from_levels(cls, levels, format=None, srgb=False):
        """A cube map from its levels as given
        (sample_texture_create_cube_levels): levels[k] holds the six faces
        of level k as Texture.cube takes them, each max(1, N >> k) square;
        a partial chain is allowed."""
        return cls._create_from_levels("cube_from_levels", levels, _lib.Image, 6,
                                       lambda lv, what: _arrays.faces(lv, format, srgb, what),
                                       _lib.core.sample_texture_create_cube_levels)

    @classmethod
    def volume(cls, array, format=None, srgb=False, mip="box", wrap="clamp_to_edge", max_levels=0):
        """A 3D texture (sample_texture_create_3d) from a (D, H, W) or
        (D, H, W, C) array: slice 0 (r = 0) first, each slice row 0 (t = 0)
        first. dtype, ``format``, ``srgb``, ``mip`` as for Texture();
        ``wrap`` is one wrap mode or an (s, t, r) triple, what the
        pyramid's kernels read past the edges; ``max_levels`` caps the
        level count (0: down to 1 x 1 x 1). Sampled at (s, t, r) with
        sample3."""
        vol, keep = _arrays.volume(array, format, srgb)
        params = _arrays.mip_params(mip, wrap, max_levels, axes=("s", "t", "r"))
        return cls._wrap(cls._create(lambda out, err: _lib.core.sample_texture_create_3d(
            ctypes.byref(vol), ctypes.byref(params), out, err), "sample_texture_create_3d"), True)

    @classmethod
    def volume_from_levels(cls, levels, format=None, srgb=False):
        """A 3D texture from its levels as given
        (sample_texture_create_3d_levels): levels[k] a (D, H, W[, C]) array
        of max(1, D >> k) x max(1, H >> k) x max(1, W >> k) with the base's
        channels and dtype; a partial chain is allowed."""
        return cls._create_from_levels("volume_from_levels", levels, _lib.Volume, 1,
                                       lambda lv, what: _arrays.as_level(_arrays.volume(lv, format, srgb, what)),
                                       _lib.core.sample_texture_create_3d_levels)

    @classmethod
    def _create_from_levels(cls, name, levels, ctype, per_level, describe, create):
        """A texture from caller-supplied levels through `create` (one of
        sample_texture_create_*levels): describe(level, what) gives a
        level's `per_level` C structs of type `ctype` and the arrays they
        point into, which are kept until `create` has copied them."""
        levels = list(levels)
        if not levels:
            raise ValueError("%s: at least one level" % name)
        structs = (ctype * (per_level * len(levels)))()
        keep = []
        for k, lv in enumerate(levels):
            level_structs, arrays = describe(lv, "levels[%d]" % k)
            structs[per_level * k:per_level * (k + 1)] = level_structs[:]
            keep += arrays
        return cls._wrap(cls._create(lambda out, err: create(structs, len(levels), out, err), create.__name__), True)

    # ---- sampling ----------------------------------------------------------

    def sample3(self, sampler, queries=None, *, p=None, dpdx=0.0, dpdy=0.0, bias=None, stats=False,
                out=None, latlong=False):
        """Sample N 9-float queries with one sampler state: a cube map by
        direction (sample_batch_cube), a 3D texture at (s, t, r)
        (sample_batch_3d), or, with ``latlong=True``, a 2D texture as a
        lat-long environment map by direction (sample_batch_latlong,
        OpenImageIO's convention with +y up: doc/environment-maps.md).

        ``queries``: an (N, 9) array of p, dp/dx, dp/dy (GLSL textureGrad's
        P, dPdx, dPdy; the order of ``texsample lookup``'s --cube, --latlong
        and --volume query files) or (N, 3, 3) with those as rows; or give
        ``p`` (N x 3) and optionally ``dpdx``, ``dpdy`` (N x 3, 3-vectors or
        0), broadcast. A C-contiguous float32 array is passed to C as it is
        (no copy). A direction may have any length but zero. ``bias``: (N,)
        per-query LOD bias; ``sampler``: a Sampler or a dict of its
        keywords (cube and lat-long maps ignore its wrap modes; a 3D texture
        uses wrap_s, wrap_t, wrap_r).

        Returns the (N, 4) float32 linear RGBA results (into ``out`` when
        given); with ``stats=True`` a Samples tuple (rgba, None, None,
        stats). A query holding NaN or inf, or a zero direction, returns the
        border colour. TypeError for a texture of the wrong kind.
        """
        sampler = as_sampler(sampler)
        entry = self._entry3(latlong)
        q = _queries9(queries, p, dpdx, dpdy)
        n = q.shape[0]
        b = None if bias is None else _arrays.float_array(bias, "bias", (), n)
        rgba = _arrays.out_array(out, "out", n)
        st = np.empty(n, _arrays.STATS_DTYPE) if stats else None
        args = _lib.Batch3Args(count=n, queries=_arrays.ptr(q), lod_bias=_arrays.ptr(b),
                               rgba=_arrays.ptr(rgba), stats=_arrays.ptr(st))
        if n:
            with self._handle as h:
                status = entry(h, ctypes.byref(sampler._state), ctypes.byref(args))
            _errors.check(status, None, entry.__name__)
        if stats:
            return _arrays.Samples(rgba, None, None, st)
        return rgba

    def _entry3(self, latlong):
        """The C entry point for this texture's 9-float queries."""
        kind = self.kind
        if latlong:
            if kind != "2d":
                raise TypeError("sample3: latlong=True reads a 2D texture as a lat-long map; this texture is %s"
                                % ("a cube map" if kind == "cube" else "a 3D texture"))
            return _lib.core.sample_batch_latlong
        if kind == "cube":
            return _lib.core.sample_batch_cube
        if kind == "3d":
            return _lib.core.sample_batch_3d
        raise TypeError("sample3: a 2D texture takes (s, t) queries through sample(); "
                        "sample3(..., latlong=True) samples it by direction as a lat-long map")

    # ---- levels ------------------------------------------------------------

    @staticmethod
    def _level_sampler(k):
        """Nearest magnification of level k alone: at a texel centre it reads
        that one texel, decoded as sample_texture_texel_layer decodes it,
        so a level comes out of one batch instead of a call per texel."""
        return Sampler(min_filter="nearest", mag_filter="nearest", wrap="clamp_to_edge", base_level=k,
                       max_level=k)

    def _level_layers(self, k):
        """Texture.level(k) of a cube map or a 3D texture: (layers, h, w, 4)."""
        w, h, d = self.level_size3(k)
        q = np.zeros((d * h * w, 9), np.float32)
        if self.kind == "cube":
            # Each texel centre's direction on its face, of |ma| = 1.
            sc = (2 * np.arange(w) + 1) / w - 1
            tc = (2 * np.arange(h) + 1) / h - 1
            tt, ss = np.meshgrid(tc, sc, indexing="ij")
            axis, u, v = (_CUBE_FRAMES[:, i, None, None, :] for i in range(3))
            q[:, :3] = (axis + ss[None, :, :, None] * u + tt[None, :, :, None] * v).reshape(-1, 3)
        else:
            kk, jj, ii = np.meshgrid(np.arange(d), np.arange(h), np.arange(w), indexing="ij")
            q[:, 0] = (ii.ravel() + 0.5) / w
            q[:, 1] = (jj.ravel() + 0.5) / h
            q[:, 2] = (kk.ravel() + 0.5) / d
        return self.sample3(self._level_sampler(k), q).reshape(d, h, w, 4)
