"""Geomatics Toolbox — QGIS Processing provider for LiDAR ground filtering, terrain
models, GCP image rectification and photogrammetric accuracy.

QGIS calls :func:`classFactory`; everything heavy is imported lazily from there so
that importing this package (e.g. ``geomatics_toolbox.core`` in headless tests) never
pulls in Qt or QGIS.
"""


def classFactory(iface):  # noqa: N802 - name required by QGIS
    """Entry point QGIS calls to create the plugin instance."""
    from .plugin import GeomaticsToolboxPlugin
    return GeomaticsToolboxPlugin(iface)
