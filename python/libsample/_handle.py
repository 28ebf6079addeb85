"""Ownership of a C texture shared by the Python objects that use it.

sample_texture_destroy() must not race with readers (sample.h §4). A
Python call that uses the texture holds it (acquire/release) for the
duration of the C call, which runs with the GIL released; close() marks
the texture closed at once and destroys it when the last holder lets go,
so closing from another thread never frees memory under a running batch,
and every use after close() raises instead of crashing.
"""
import threading

from . import _lib


class ClosedTextureError(ValueError):
    """The texture was closed (or its owner released it)."""


class Handle:
    __slots__ = ("_ptr", "_owned", "_users", "_closing", "_lock")

    def __init__(self, ptr, owned=True):
        self._ptr = ptr
        self._owned = owned
        self._users = 0
        self._closing = False
        self._lock = threading.Lock()

    @property
    def closed(self):
        return self._closing

    def acquire(self):
        with self._lock:
            if self._closing:
                raise ClosedTextureError("libsample.Texture: the texture is closed")
            self._users += 1
            return self._ptr

    def release(self):
        with self._lock:
            self._users -= 1
            if self._closing and self._users == 0:
                self._destroy()

    def close(self):
        with self._lock:
            if self._closing:
                return
            self._closing = True
            if self._users == 0:
                self._destroy()

    def _destroy(self):
        ptr, self._ptr = self._ptr, None
        if self._owned and ptr:
            _lib.core.sample_texture_destroy(ptr)

    def __enter__(self):
        return self.acquire()

    def __exit__(self, *exc):
        self.release()
