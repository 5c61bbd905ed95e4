"""The exceptions and warnings of the candela module (docs/python.md)."""


class InputError(Exception):
    """Bad input: a case, scene, luminaire or weather file, or an argument, that candela refuses.

    The command line exits with code 2 and prints the same one line, ``file:line: message``.

    Attributes:
        file: the file (or argument) at fault, e.g. ``case.toml`` or ``points``.
        line: its line (1-based; for an array of points, the row); 0 when only the file is known.
        message: what is wrong, without the location.
    """

    def __init__(self, text, file="", line=0, message=None):
        super().__init__(text)
        self.file = file
        self.line = line
        self.message = text if message is None else message


class CandelaWarning(UserWarning):
    """Input that is valid but probably not what was meant (docs/warnings.md).

    Attributes: code (the stable snake_case name), file, line and message, as in summary.json's
    ``warnings``.
    """

    def __init__(self, text, code="", file="", line=0, message=""):
        super().__init__(text)
        self.code = code
        self.file = file
        self.line = line
        self.message = message
