"""Plumbing shared by the LiDAR ground-filter algorithms (over core.lidar.pipeline)."""
from __future__ import annotations

from ..core.io.las import las_info
from ..core.lidar.pipeline import FilterOutputs, classify_file
from ..core.progress import Monitor
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

    def classify_and_publish(self, src, algorithm, outputs, selection, context,
                             feedback) -> dict:
        """Run ``algorithm`` on ``src`` through the pipeline, log the counts, load the
        classified cloud into the project on completion; the output numbers and paths
        (N_NOISE: every class-7 point of the output)."""
        self.log_units(feedback, las_info(src).units)
        s = classify_file(src, algorithm, outputs, Monitor(**self.core_callbacks(feedback)),
                          selection=selection)
        filt = s.seconds.get("filter") or 0.0
        feedback.pushInfo(self.tr("{} points: {} ground, {} non-ground, {} low outliers; "
                                  "filter {:.1f} s").format(
            s.n_points, s.n_ground, s.n_nonground, s.n_noise, filt))
        result = {"N_POINTS": s.n_points, "N_GROUND": s.n_ground,
                  "N_NONGROUND": s.n_nonground, "N_NOISE": s.n_noise,
                  "POINTS_PER_SECOND": s.n_points / filt if filt > 0 else None}
        self.load_cloud_on_completion(context, outputs.cloud,
                                      self.tr("Classified point cloud"), self.OUTPUT)
        return {**result, **self.filter_results(outputs)}
