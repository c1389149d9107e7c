"""LiDAR point-cloud processing: ground filters, low-noise flags, filter accuracy.

Public ground filters re-exported here: the recommended filter
(:func:`classify_ground`, :class:`RecommendedOptions`; Pingel et al. 2013 after
Zhang et al. 2003) and progressive TIN densification (:func:`classify_ptd`,
:class:`PtdOptions`; Axelsson 2000).
"""
from .ptd import PtdOptions, ptd_filter
from .ptd import classify as classify_ptd
from .recommended import RecommendedOptions, recommended_filter
from .recommended import classify as classify_ground

__all__ = ["PtdOptions", "RecommendedOptions", "classify_ground", "classify_ptd",
           "ptd_filter", "recommended_filter"]
