"""Exceptions of the chatter package.

Every error carries the rejection ``code`` (a stable kebab-case string such as ``"no-cone"``,
``"kappa-not-positive"`` or a kernel rejection code such as ``"image-outside"``) and the
``exit_code`` that the command line ``chatter`` would exit with (1 negative answer, 2 bad or
unreadable input, 3 internal error).
"""


class ChatterError(Exception):
    """Base class of every error raised by chatter: ``.code``, ``.message``, ``.exit_code``."""

    exit_code = 2

    def __init__(self, message, code=None):
        super().__init__(message)
        self.message = message
        self.code = code

    def __str__(self):
        return f"[{self.code}] {self.message}" if self.code else self.message


class UsageError(ChatterError, ValueError):
    """Bad input (n = 1, kappa <= 0, a malformed number, ...) or unreadable input (exit 2)."""

    exit_code = 2


class NotCertifiedError(ChatterError):
    """No certificate could be made (exit 1); ``.code`` says why, e.g. ``"no-cone"``."""

    exit_code = 1


class InternalError(ChatterError):
    """A bug: the two bignum backends disagree, or chatter panicked (exit 3)."""

    exit_code = 3
