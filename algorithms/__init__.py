"""Processing algorithms: thin wrappers over :mod:`geomatics_toolbox.core`.

:func:`all_algorithms` is the single registry the provider loads; add one import
and one entry per algorithm.
"""


def all_algorithms():
    """Fresh instances of every algorithm the provider offers."""
    from .buildings import BuildingsAlgorithm
    from .catalog import CatalogAlgorithm
    from .classify import ClassifyAlgorithm
    from .dtm_accuracy import DtmAccuracyAlgorithm
    from .elevation_change import ElevationChangeAlgorithm
    from .filter_accuracy import GroundFilterAccuracyAlgorithm
    from .gcp_batch import RectifyBatchAlgorithm
    from .gcp_rectification import GcpAccuracyReportAlgorithm, RectifyGcpAlgorithm
    from .ground_filter import GroundFilterAlgorithm, PtdGroundFilterAlgorithm
    from .gsd_calculator import GsdBatchAlgorithm, GsdCalculatorAlgorithm
    from .install_dependencies import InstallDependenciesAlgorithm
    from .lidar_qa import LidarQaAlgorithm
    from .lidar_to_dtm import LidarToDtmAlgorithm
    from .lsq_filter import LsqGroundFilterAlgorithm
    from .publish_outputs import PublishOutputsAlgorithm
    from .slope_filter import SlopeGroundFilterAlgorithm, SlopeThresholdSweepAlgorithm
    from .terrain import DsmAlgorithm, IdwDtmAlgorithm, KrigingDtmAlgorithm
    from .tin_dtm import TinDtmAlgorithm

    return [
        GsdCalculatorAlgorithm(),
        GsdBatchAlgorithm(),
        RectifyGcpAlgorithm(),
        GcpAccuracyReportAlgorithm(),
        RectifyBatchAlgorithm(),
        IdwDtmAlgorithm(),
        KrigingDtmAlgorithm(),
        DsmAlgorithm(),
        TinDtmAlgorithm(),
        DtmAccuracyAlgorithm(),
        LidarToDtmAlgorithm(),
        PublishOutputsAlgorithm(),
        SlopeGroundFilterAlgorithm(),
        SlopeThresholdSweepAlgorithm(),
        LsqGroundFilterAlgorithm(),
        GroundFilterAccuracyAlgorithm(),
        CatalogAlgorithm(),
        LidarQaAlgorithm(),
        ElevationChangeAlgorithm(),
        BuildingsAlgorithm(),
        ClassifyAlgorithm(),
        GroundFilterAlgorithm(),
        PtdGroundFilterAlgorithm(),
        InstallDependenciesAlgorithm(),
    ]
