"""Processing algorithms: thin wrappers over :mod:`geomatics_toolbox.core`.

:func:`all_algorithms` is the single registry the provider loads; add one import
and one entry per algorithm.
"""


def all_algorithms():
    """Fresh instances of every algorithm the provider offers."""
<<<<<<< HEAD
    from .catalog import CatalogAlgorithm
=======
    from .buildings import BuildingsAlgorithm
>>>>>>> cf7e7e9 (Building footprints (geomatics:buildings): TIN DTM, k-NN plane normals, region growing within 20°, patches >= 15 m², GeoPackage footprints with height/area/volume/storeys/roof type, optional class 6 cloud; synthetic accuracy evaluator; benchmark rows (Whitebox classify_buildings_in_lidar needs footprints as input); ar/fa)
    from .dtm_accuracy import DtmAccuracyAlgorithm
    from .elevation_change import ElevationChangeAlgorithm
    from .filter_accuracy import GroundFilterAccuracyAlgorithm
    from .gcp_rectification import GcpAccuracyReportAlgorithm, RectifyGcpAlgorithm
    from .gsd_calculator import GsdBatchAlgorithm, GsdCalculatorAlgorithm
    from .lidar_qa import LidarQaAlgorithm
    from .lsq_filter import LsqGroundFilterAlgorithm
    from .slope_filter import SlopeGroundFilterAlgorithm, SlopeThresholdSweepAlgorithm
    from .terrain import DsmAlgorithm, IdwDtmAlgorithm, KrigingDtmAlgorithm
    from .tin_dtm import TinDtmAlgorithm

    return [
        GsdCalculatorAlgorithm(),
        GsdBatchAlgorithm(),
        RectifyGcpAlgorithm(),
        GcpAccuracyReportAlgorithm(),
        IdwDtmAlgorithm(),
        KrigingDtmAlgorithm(),
        DsmAlgorithm(),
        TinDtmAlgorithm(),
        DtmAccuracyAlgorithm(),
        SlopeGroundFilterAlgorithm(),
        SlopeThresholdSweepAlgorithm(),
        LsqGroundFilterAlgorithm(),
        GroundFilterAccuracyAlgorithm(),
<<<<<<< HEAD
        CatalogAlgorithm(),
=======
        LidarQaAlgorithm(),
        ElevationChangeAlgorithm(),
<<<<<<< HEAD
>>>>>>> f9216f7 (Point density and quality (geomatics:lidarqa) with numeric ELiT advice, maps and histograms; elevation change (geomatics:elevationchange): LoD95, cut/fill polygons to GeoPackage (core/io/vector.py), report; ar/fa)
=======
        BuildingsAlgorithm(),
>>>>>>> cf7e7e9 (Building footprints (geomatics:buildings): TIN DTM, k-NN plane normals, region growing within 20°, patches >= 15 m², GeoPackage footprints with height/area/volume/storeys/roof type, optional class 6 cloud; synthetic accuracy evaluator; benchmark rows (Whitebox classify_buildings_in_lidar needs footprints as input); ar/fa)
    ]
