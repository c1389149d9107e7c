"""Batch GCP rectification: a folder of images with their ``.points`` files.

Each image ``name.ext`` with the QGIS Georeferencer's ``name.ext.points`` next to it is
assessed (:func:`~.assess.assess_gcps`, criteria of Tishreen Univ. J. Eng. Sci.
38(2), 2016) with a fixed or the recommended transformation and warped through GDAL
(:func:`~.warp.rectify`) into ``<output folder>/name_rectified.tif``, each under its
own all-or-nothing output contract. One summary row per image: transformation, RMS_T,
the check-point / leave-one-out RMS_T, the verdict (or the error that stopped it).
"""
from __future__ import annotations

import csv
import io
import os
from dataclasses import dataclass
from typing import List, Optional

from ..errors import InputError
from ..io.contract import OutputContract
from ..io.gcp import check_in_image, read_gcps
from ..progress import Cancelled, Monitor
from ..reporting import Paragraph, Report, T, Table
from .assess import assess_gcps
from .report import KIND_NAMES
from .warp import image_info, rectify

#: image extensions looked for in the input folder
IMAGE_EXTENSIONS = (".tif", ".tiff", ".png", ".jpg", ".jpeg", ".jp2", ".img", ".vrt")


@dataclass
class BatchRow:
    """The outcome of one image of a batch."""

    image: str
    output: str = ""
    kind: str = ""
    n_gcps: int = 0
    rms_t: Optional[float] = None
    honest_rms_t: Optional[float] = None
    basis: str = ""
    verdict: str = ""
    dropped: int = 0
    error: str = ""


def find_images(folder) -> List[tuple]:
    """Return ``(image, points)`` pairs of ``folder`` (images with a ``.points`` file).

    Raises
    ------
    InputError
        When the folder does not exist or holds no image with its ``.points`` file.
    """
    folder = os.fspath(folder)
    if not os.path.isdir(folder):
        raise InputError("INPUT_FOLDER: {folder} is not a folder.", folder=folder)
    pairs = [(os.path.join(folder, n), os.path.join(folder, n + ".points"))
             for n in sorted(os.listdir(folder))
             if n.lower().endswith(IMAGE_EXTENSIONS)
             and os.path.isfile(os.path.join(folder, n + ".points"))]
    if not pairs:
        raise InputError("No image with its Georeferencer .points file (image.tif + "
                         "image.tif.points) in {folder}.", folder=folder)
    return pairs


def output_name(image: str, out_folder: str) -> str:
    """Return ``<out_folder>/<stem>_rectified.tif`` for ``image``."""
    stem = os.path.splitext(os.path.basename(image))[0]
    return os.path.join(out_folder, f"{stem}_rectified.tif")


def rectify_one(image: str, points: str, out_folder: str, *, kind: str, crs: str = "",
                refine: bool = False, resampling: str = "near", cancel=None) -> BatchRow:
    """Assess and warp one image under its own output contract; errors go in the row."""
    row = BatchRow(os.path.basename(image))
    out = output_name(image, out_folder)
    try:
        g = read_gcps(points, crs=crs, source_geotransform=image_info(image)[3])
        if not g.crs:
            raise InputError("the .points file has no '#CRS:' line; set GCP_CRS.")
        w, h, _, _ = image_info(image)
        check_in_image(g, w, h)
        a = assess_gcps(g, kind=kind, image_size=(w, h), refine=refine, cancel=cancel)
        with OutputContract({"OUTPUT": out}, inputs={"INPUT": image,
                                                      "GCP_FILE": points}) as c:
            rectify(image, a.gcps, c.path("OUTPUT"), kind=a.kind, resampling=resampling,
                    cancel=cancel)
        r = a.selected
        row.output, row.kind, row.n_gcps = out, a.kind, r.n_gcps
        row.rms_t, row.honest_rms_t = r.fit.rms_t, r.score(a.comparison.basis)
        row.basis, row.verdict, row.dropped = a.comparison.basis, a.verdict, len(a.dropped)
    except Cancelled:
        raise
    except ValueError as exc:  # InputError and the core's clear ValueErrors
        row.error = str(exc)
    return row


def check_batch(pairs, folder, out_folder) -> None:
    """Refuse, before anything is created, a batch whose outputs would collide.

    The output folder is compared with the input folder after resolving links (a
    symlink to the input folder is the input folder); two images with one stem
    (``a.tif`` and ``a.png``) would both become ``a_rectified.tif``.
    """
    if os.path.realpath(out_folder) == os.path.realpath(os.fspath(folder)):
        raise InputError("OUTPUT_FOLDER must differ from INPUT_FOLDER (the rectified "
                         "images would sit among the inputs).")
    seen = {}
    for image, _ in pairs:
        name = os.path.normcase(output_name(image, out_folder))
        if name in seen:
            raise InputError("{a} and {b} would both be written as {out}; rename one of "
                             "them (one result would be lost).",
                             a=os.path.basename(seen[name]), b=os.path.basename(image),
                             out=os.path.basename(name))
        seen[name] = image


def rectify_folder(folder, out_folder, *, kind: str = "recommended", crs: str = "",
                   refine: bool = False, resampling: str = "near", progress=None,
                   cancel=None, log=None) -> List[BatchRow]:
    """Rectify every image of ``folder`` that has a ``.points`` file.

    Parameters
    ----------
    folder, out_folder : path-like
        Input folder; output folder (created if missing, never the input folder).
    kind : str
        A transformation of :data:`~.transforms.KINDS` or ``'recommended'`` (per image).
    crs : str
        CRS of the GCPs when a ``.points`` file has no ``#CRS:`` line.
    refine : bool
        Drop GCPs over the C5 limit first (``gdalwarp -refine_gcps``).
    resampling : str
        GDAL resampling.
    progress, cancel, log : callable, optional
        Progress (0–1), cancel test, and a message sink called once per image.

    Returns
    -------
    list of BatchRow
    """
    pairs = find_images(folder)
    out_folder = os.fspath(out_folder)
    check_batch(pairs, folder, out_folder)
    os.makedirs(out_folder, exist_ok=True)
    mon = Monitor(progress, cancel)
    rows = []
    for k, (image, points) in enumerate(pairs):
        mon.step(k / len(pairs))
        row = rectify_one(image, points, out_folder, kind=kind, crs=crs, refine=refine,
                          resampling=resampling, cancel=cancel)
        rows.append(row)
        if log is not None:
            log(row)
    mon.update(1.0)
    return rows


def summary_csv(rows: List[BatchRow]) -> str:
    """Return the summary table as CSV text (one row per image)."""
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(["image", "output", "transformation", "n_gcps", "rms_t", "honest_rms_t",
                "honest_basis", "verdict", "dropped", "error"])
    for r in rows:
        w.writerow([r.image, r.output, r.kind, r.n_gcps,
                    "" if r.rms_t is None else f"{r.rms_t:.6f}",
                    "" if r.honest_rms_t is None else f"{r.honest_rms_t:.6f}",
                    r.basis, r.verdict, r.dropped, r.error])
    return buf.getvalue()


def summary_report(rows: List[BatchRow]) -> Report:
    """Return the batch summary as a translatable :class:`~..reporting.Report`."""
    rep = Report("GCP rectification — batch summary")
    ok = sum(1 for r in rows if not r.error)
    rep.summary.append(Paragraph(T("{ok} of {n} images rectified.", ok=ok, n=len(rows)),
                                 "ok" if ok == len(rows) else "fail"))
    table = [[r.image, T(KIND_NAMES[r.kind]) if r.kind else "–", r.n_gcps, r.rms_t, r.honest_rms_t,
              T("leave-one-out" if r.basis == "loo" else "check points") if r.basis
              else "–", T(r.verdict) if r.verdict else "–", r.dropped, r.error or "–"]
             for r in rows]
    rep.section("Images").add(Table(
        ["image", "transformation", "n", "fit RMS_T", "check / leave-one-out RMS_T",
         "judged on", "verdict", "dropped", "error"], table, digits=4))
    rep.section("Notes").add(Paragraph(
        "RMS_T in the map units of each image's GCP CRS. The verdict of a polynomial is "
        "the paper's criteria on the fit residuals; of the other transformations, on the "
        "check-point (else leave-one-out) residuals.", "note"))
    return rep
