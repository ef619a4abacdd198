# Type stubs of asperity.plot (plot.py): the common contact figures with matplotlib.
from typing import Iterable, List, Literal, Mapping, Optional, Sequence, Tuple, Union

from matplotlib.axes import Axes
from matplotlib.figure import Figure

from . import ContactModel

Models = Union[ContactModel, Sequence[ContactModel], Mapping[str, ContactModel]]
LoadRange = Optional[Tuple[float, float]]

def load_separation(models: Models, labels: Optional[Iterable[str]] = None, *, load_range: LoadRange = None,
                    points: int = 200, separation: Literal["mean", "origin"] = "mean",
                    ax: Optional[Axes] = None) -> Axes: ...
def area_load(models: Models, labels: Optional[Iterable[str]] = None, *, load_range: LoadRange = None,
              points: int = 200, ax: Optional[Axes] = None) -> Axes: ...
def stiffness_load(models: Models, labels: Optional[Iterable[str]] = None, *, load_range: LoadRange = None,
                   points: int = 200, ax: Optional[Axes] = None) -> Axes: ...
def contact_figure(models: Models, labels: Optional[Iterable[str]] = None, *, load_range: LoadRange = None,
                   points: int = 200, separation: Literal["mean", "origin"] = "mean") -> Tuple[Figure, List[Axes]]: ...
