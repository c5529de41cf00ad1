"""The one exception the readers raise for a file they cannot use."""


class EjectaFileError(ValueError):
    """A file that is missing, not what it claims to be, or lacks what ejecta writes into it.

    The message names the file, the object inside it where there is one, and the reason, as the
    ejecta command line does: "runs/demo/snapshots/snap_0003.h5: '/particles/density': missing".
    """

    def __init__(self, path, reason, item=None):
        self.path = str(path)
        self.item = item
        self.reason = reason
        where = "%s: '%s'" % (self.path, item) if item else self.path
        super().__init__("%s: %s" % (where, reason))
