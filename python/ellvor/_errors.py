"""The exceptions of ellvor.

``Error`` (a ``RuntimeError``) is anything that went wrong inside ellvor;
``InputError`` (also a ``ValueError``) is bad input: a site file that does not
parse, a number that is not finite, two sites that cross.  Its message is the
CLI's, ``FILE:LINE:COLUMN: what was expected`` for input read from a file.
"""


class Error(RuntimeError):
    """An ellvor computation failed (an internal limit, an I/O error)."""


class InputError(Error, ValueError):
    """Bad input.

    Attributes (``None`` when they do not apply):
        filename, lineno, column -- where in a file (1-based), as the CLI prints them;
        reason -- the message without the location;
        sites -- ``(i, j)`` for a bad pair of sites (crossing or duplicate), site ids, i < j;
        why -- for two sites that cross in a way the diagram does not accept: how (e.g. "their boundaries
            meet in 4 points ...").
    """

    def __init__(self, message, filename=None, lineno=None, column=None, sites=None, reason=None, why=None):
        super().__init__(message)
        self.filename = filename
        self.lineno = lineno
        self.column = column
        self.sites = sites
        self.reason = message if reason is None else reason
        self.why = why


# Shown as ellvor.Error and ellvor.InputError in tracebacks.
Error.__module__ = InputError.__module__ = "ellvor"
