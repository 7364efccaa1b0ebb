"""The exceptions of airshape: every failure is an `Error` carrying the file and the CPACS
path of the node it concerns (empty when not known)."""


class Error(Exception):
    """A failure of airshape: `file` and `cpacs_path` say where, when known."""

    def __init__(self, message: str, file: str = "", cpacs_path: str = "") -> None:
        super().__init__(message)
        self.file = file
        self.cpacs_path = cpacs_path


class FileError(Error):
    """The input is missing, not XML, not CPACS, or a CPACS version other than 3."""


class ModelError(Error):
    """The document breaks a rule the geometry needs (a dangling uIDref, a cycle, a failed build)."""


class ArgumentError(Error):
    """An argument is out of range or names nothing (an index, eta, a uID, an XPath, a value)."""


class WriteError(Error):
    """An output file could not be written (nothing is left under its name)."""


class PluginError(Error):
    """A plugin could not be loaded or registered."""


class NotBuiltYetError(Error):
    """The request needs a component builder that does not exist yet."""
