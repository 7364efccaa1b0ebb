"""Design studies: parameter sweeps of a CPACS file on a local pool of worker processes or a
Dask cluster, and sensitivities of outputs to parameters (docs/studies.md)."""
from .definition import Export, Output, Parameter, Sample, Study, StudyError
from .runner import Outcome
from .sensitivity import sensitivities

__all__ = ["Export", "Outcome", "Output", "Parameter", "Sample", "Study", "StudyError", "sensitivities"]
