"""Camera presets for the GSD / accuracy calculator.

Each preset gives the *true* focal length (not the 35 mm equivalent), the sensor
size and the image size in pixels of the sensor's full-resolution still image, with
the source of the figures. The GSD relation used by drone planning tools,
GSD = H·S_W/(Im_w·F_R), reproduces the manufacturers' own GSD rules of thumb for
these cameras (e.g. DJI's "GSD = H/36.5 cm/px" for the Phantom 4 RTK).
"""
from __future__ import annotations

from dataclasses import dataclass

from ..errors import InputError


@dataclass(frozen=True)
class Camera:
    """Interior geometry of a camera as the GSD formulas need it."""

    key: str
    name: str
    sensor_width_mm: float
    sensor_height_mm: float
    image_width_px: int
    image_height_px: int
    focal_length_mm: float
    source: str

    @property
    def pixel_pitch_um(self) -> float:
        """Pixel pitch w = S_W / Im_w, micrometres."""
        return 1000.0 * self.sensor_width_mm / self.image_width_px


CAMERAS = {
    c.key: c for c in (
        Camera("nikon_p100", "Nikon Coolpix P100 (Al Khalil 2019)", 6.123, 4.592, 3648, 2736,
               4.6, "Al Khalil 2019, worked example: S_W 6.123 mm, F_R 4.6 mm, 3648 px "
               "(pixel 1.6787 µm); 4:3 image 3648 × 2736 px"),
        Camera("dji_p4rtk", "DJI Phantom 4 RTK / 4 Pro (FC6310, 1\" CMOS)", 13.2, 8.8, 5472,
               3648, 8.8, "DJI Phantom 4 RTK specifications: 1\" CMOS 13.2 × 8.8 mm, "
               "5472 × 3648 px (3:2), lens 8.8 mm (24 mm equiv.); DJI states "
               "GSD = H/36.5 cm/px"),
        Camera("dji_p1_35", "DJI Zenmuse P1 with DL 35 mm lens", 35.9, 24.0, 8192, 5460,
               35.0, "DJI Zenmuse P1 specifications: full-frame 35.9 × 24 mm, "
               "8192 × 5460 px (3:2), pixel 4.4 µm, DL 35 mm F2.8 LS ASPH lens"),
        Camera("phaseone_ixm100_80", "Phase One iXM-100 with RSM 80 mm lens", 53.4, 40.0,
               11664, 8750, 80.0, "Phase One iXM-100 specifications: 53.4 × 40.0 mm "
               "sensor, 11664 × 8750 px, pixel 3.76 µm; RSM 80 mm lens"),
    )
}


def camera(key: str) -> Camera:
    """Preset by key; ``ValueError`` listing the known keys otherwise."""
    try:
        return CAMERAS[key]
    except KeyError:
        raise InputError("Unknown camera preset {key}; known presets: {presets} (or enter "
                         "the values yourself).", key=repr(key),
                         presets=", ".join(CAMERAS)) from None
