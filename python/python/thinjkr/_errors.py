"""The exceptions of thinjkr: one base class and a subclass per kind of
the solver's typed errors (its messages name the parameter and its allowed
range, as the command line's do)."""

from __future__ import annotations

from typing import Optional


class ThinJkrError(Exception):
    """Base class of every thinjkr error. ``kind`` is the solver's name for
    the failure (``out_of_range``, ``no_state``, ``no_convergence``, …).
    The message is at most 300 characters, as the command line's; where it
    is shortened, ``record`` holds the whole (an exact search's every
    route), else it is the message."""

    def __init__(self, message: str, kind: str = "error", record: Optional[str] = None):
        super().__init__(message)
        self.kind = kind
        self.record = message if record is None else record

    def __reduce__(self):
        return (type(self), (str(self), self.kind, self.record))


class InvalidInput(ThinJkrError, ValueError):
    """Bad input: a parameter outside its allowed or supported range, or an
    incomplete request. Also a ``ValueError``."""


class NoState(ThinJkrError):
    """The model has no state at that input (below pull-off, beyond the
    branch, a band of the exact family)."""


class NoConvergence(ThinJkrError):
    """Newton's method did not converge; the message says where."""


class Unresolved(ThinJkrError):
    """The exact solver does not resolve the answer with the contour modes
    it tried; no number is given."""


class Unavailable(ThinJkrError):
    """The model lacks what was asked for (a closed form its derivation
    could not produce, a control it does not take)."""


class IOFailure(ThinJkrError, OSError):
    """Reading or writing failed."""


class ThinJkrWarning(UserWarning):
    """A result the solver answers but doubts (an input outside the model's
    stated range, coatings not thin against the contact): the same words
    as the command line's warnings. Silence it or turn it into an error as
    any warning (``warnings.simplefilter("error", thinjkr.ThinJkrWarning)``)."""


_KINDS = {
    "out_of_range": InvalidInput,
    "unsupported": InvalidInput,
    "usage": InvalidInput,
    "no_state": NoState,
    "no_convergence": NoConvergence,
    "unresolved": Unresolved,
    "unavailable": Unavailable,
    "io": IOFailure,
}


def error_class(kind: str):
    """The exception class for a solver error kind."""
    return _KINDS.get(kind, ThinJkrError)


def _raise(raw) -> None:
    kind, message, record = raw.args
    raise error_class(kind)(message, kind, record) from None
