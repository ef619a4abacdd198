# Type stubs of asperity.batch (python/asperity/batch.py). python/tests/test_stubs.py checks them against
# the submodule: names and parameters.
import os
from typing import Any, Dict, Iterable, List, Optional, Sequence, Union

from .topography import AnalysisOptions

PathLike = Union[str, bytes, os.PathLike]
Row = Dict[str, Any]

COLUMNS: List[str]

def analyse_files(paths: Iterable[PathLike], output_dir: PathLike, options: Optional[AnalysisOptions] = None, *,
                  bootstrap: Optional[int] = None, seed: Optional[int] = None, confidence: Optional[float] = None,
                  significance: Optional[float] = None, contact_modulus: Optional[float] = None,
                  pressures: Optional[Sequence[float]] = None, nominal_area: Optional[float] = None,
                  table_path: Optional[PathLike] = None, scheduler: Any = None, n_workers: Optional[int] = None,
                  threads_per_worker: Optional[int] = None, processes: bool = True,
                  analysis_threads: Optional[int] = 1, progress: bool = True, resume: bool = True) -> List[Row]: ...
def row_from_json(document: Union[str, bytes, Dict[str, Any]], source: Optional[str] = None,
                  name: Optional[str] = None) -> Row: ...
def options_fingerprint(options: Union[AnalysisOptions, Dict[str, Any], None] = None) -> str: ...
def output_name(path: PathLike) -> str: ...
def read_table(path: PathLike) -> List[Row]: ...
