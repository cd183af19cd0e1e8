"""ExactMAT: the medial axis transform of domains bounded by exact NURBS, as VTK filters.

    from exactmat import vtkNURBSSource
    source = vtkNURBSSource()
    source.SetShapeName("annulus")
    source.Update()

Every class composes with VTK's own (``vtkmodules``) in a pipeline. Errors from bad input
are reported as VTK errors (``vtkErrorMacro``) and the failing pipeline produces no
output; see ``exactmat.ErrorObserver`` to turn them into Python exceptions.
"""

# VTK's own modules first: the wrapped classes derive from them.
from vtkmodules import vtkCommonCore as _vtkCommonCore  # noqa: F401
from vtkmodules import vtkCommonDataModel as _vtkCommonDataModel  # noqa: F401
from vtkmodules import vtkCommonExecutionModel as _vtkCommonExecutionModel  # noqa: F401
from vtkmodules import vtkIOCore as _vtkIOCore  # noqa: F401

from vtkmodules.util.vtkConstants import VTK_STRING as _VTK_STRING

from .ExactMATFiltersMedial import *  # noqa: F401,F403
from .ExactMATIONURBS import *  # noqa: F401,F403
from .ExactMATIOCAD import *  # noqa: F401,F403


class ExactMATError(RuntimeError):
    """An error reported by an ExactMAT (or VTK) algorithm during Update()."""


class ErrorObserver:
    """Collects the VTK error events of algorithms; `check()` raises them as ExactMATError.

        errors = ErrorObserver()
        errors.watch(source)
        source.Update()
        errors.check()        # raises ExactMATError("... names the entity ...")
    """

    # Tells VTK to pass the error text as the call data.
    CallDataType = _VTK_STRING

    def __init__(self):
        self.messages = []

    def __call__(self, caller, event, data=None):
        self.messages.append(str(data) if data is not None else event)

    def watch(self, *algorithms):
        for algorithm in algorithms:
            algorithm.AddObserver("ErrorEvent", self)
        return self

    def check(self):
        if self.messages:
            text = "\n".join(self.messages)
            self.messages = []
            raise ExactMATError(text)
