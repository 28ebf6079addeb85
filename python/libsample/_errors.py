"""Exceptions raised for errors the C library reports."""
from . import _lib

# sample_status values (sample.h) that mean "the arguments were wrong".
_ARGUMENT_STATUSES = (1, 2, 3)  # INVALID_ARGUMENT, BAD_SIZE, TOO_LARGE


class LibsampleError(RuntimeError):
    """An error reported by libsample or libsample_io.

    ``status`` is the C ``sample_status`` value, ``status_name`` its name
    (``sample_strerror``) and ``message`` the library's ``sample_error``
    message (the offending values included), which is also ``str(e)``.
    """

    def __init__(self, status, message):
        self.status = int(status)
        self.status_name = _lib.core.sample_strerror(self.status).decode()
        self.message = message or self.status_name
        super().__init__(self.message)


class LibsampleArgumentError(LibsampleError, ValueError):
    """A LibsampleError for bad arguments (invalid argument, bad size, too
    large): also a ValueError."""


def make_error(status, message=""):
    cls = LibsampleArgumentError if status in _ARGUMENT_STATUSES else LibsampleError
    return cls(status, message)


def check(status, err=None, what=None):
    """Raise for a status other than SAMPLE_OK, with err's message."""
    if status == 0:
        return
    msg = err.message.decode(errors="replace") if err is not None else ""
    if not msg:
        msg = _lib.core.sample_strerror(status).decode()
    raise make_error(status, "%s: %s" % (what, msg) if what else msg)
