"""Plumbing shared by the LiDAR ground-filter algorithms (over core.lidar.pipeline)."""
from __future__ import annotations

from ..core.lidar.pipeline import FilterOutputs
from .base import GeomaticsAlgorithm


class LidarFilterMixin(GeomaticsAlgorithm):
    """Builds the pipeline's :class:`FilterOutputs` from Processing parameters."""

    GROUP = "lidarfiltering"

    def filter_outputs(self, parameters, context, *, cloud=None, ground=None, report=None,
                       text=None, inputs=None) -> FilterOutputs:
        """Requested outputs by role, named after their parameters."""
        names, paths = {}, {}
        for role, pname in (("cloud", cloud), ("ground", ground), ("report", report),
                            *((text or {}).items())):
            if not pname:
                continue
            names[role] = pname
            value = parameters.get(pname) if parameters else None
            if value not in (None, ""):
                path = self.parameterAsFileOutput(parameters, pname, context)
                if path:
                    paths[role] = path
        return FilterOutputs(
            cloud=paths.get("cloud"), ground=paths.get("ground"),
            report=paths.get("report"),
            text={r: p for r, p in paths.items() if r not in ("cloud", "ground", "report")},
            names=names, inputs=dict(inputs or {}), lang=self.report_lang(parameters, context),
            render=lambda rep: self.render_report(rep, parameters, context))

    @staticmethod
    def filter_results(outputs: FilterOutputs) -> dict:
        """``{parameter name: path}`` of every written output."""
        return {outputs.name(role): path for role, path in outputs.by_role().items()}
