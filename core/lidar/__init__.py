"""LiDAR point clouds: ground filters, the verbs that run them, catalogs, products.

The public surface of the sub-package (modules starting with ``_`` are private):

* the one registry of ground filters and the array verb (:mod:`.filters`):
  :data:`GROUND_FILTERS`, :func:`ground_filter`, :func:`default_ground_filter`,
  :func:`default_selection`, :func:`classify_points`, :func:`register_ground_filter`;
* the protocol (:class:`GroundFilter`, :class:`FunctionFilter`, :class:`OptionsFilter`,
  :class:`FilterOutcome`) and the point selection (:class:`SelectionOptions`);
* the file runner :func:`classify_file` with :class:`FilterOutputs`;
* the filters' options: :class:`RecommendedOptions` (Pingel et al. 2013 after Zhang et
  al. 2003), :class:`PtdOptions` (Axelsson 2000), :class:`LsqOptions` (Damascus Univ.
  J. Eng. Sci. 29(2), 2013), :class:`SlopeOptions` (Vosselman 2000);
* tile catalogs (:mod:`.catalog`): :func:`run_catalog`, :class:`Catalog`.
"""
from ._filter import FilterOutcome, FunctionFilter, GroundFilter, OptionsFilter
from ._selection import SelectionOptions
from .filters import (
    GROUND_FILTERS,
    classify_points,
    default_ground_filter,
    default_selection,
    ground_filter,
    register_ground_filter,
    run_filter,
)
from .lsq import LsqOptions
from .pipeline import ClassifyRun, FilterOutputs, classify_file
from .ptd import PtdOptions, ptd_filter
from .ptd import classify as classify_ptd
from .recommended import RecommendedOptions, recommended_filter
from .recommended import classify as classify_ground
from .slope import SlopeOptions

__all__ = ["GROUND_FILTERS", "ground_filter", "default_ground_filter", "default_selection",
           "classify_points", "run_filter", "register_ground_filter", "GroundFilter",
           "FunctionFilter", "OptionsFilter", "FilterOutcome", "SelectionOptions",
           "classify_file", "FilterOutputs", "ClassifyRun", "RecommendedOptions",
           "PtdOptions", "LsqOptions", "SlopeOptions", "classify_ground", "classify_ptd",
           "ptd_filter", "recommended_filter"]
