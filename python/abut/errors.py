"""The exceptions of the abut package."""


class DeckError(ValueError):
    """An error in a deck, located as the command-line program prints it.

    ``str(error)`` is the program's message after ``error:``, e.g.
    ``deck.k:12: *CONTACT, field 'pfac': must be positive``; the parts are attributes:
    ``file``, ``line`` (1-based, 0 when unknown), ``keyword``, ``field`` and ``message``
    (what is expected, without the location).
    """

    def __init__(self, text, file="", line=0, keyword="", field="", message=""):
        super().__init__(text)
        self.file = file
        self.line = line
        self.keyword = keyword
        self.field = field
        self.message = message or text


class InstabilityError(RuntimeError):
    """A run that went unstable. The last good state was written first; ``results`` (when
    set) reads the output directory."""

    def __init__(self, text, results=None):
        super().__init__(text)
        self.results = results


class ContactSetupError(ValueError):
    """Contact settings or surfaces the library cannot work with; ``setting`` names the setting
    (``"friction"``, ...) or the surface (``"surface1"``, ``"surface2"``)."""

    def __init__(self, text, setting=""):
        super().__init__(text)
        self.setting = setting
