"""One decoding rule for the text files users make (GCP lists and check points).

UTF-16 with a BOM, UTF-8 with or without one, else the machine's Windows code page
(Windows-1252 on UTF-8 systems); binary or undecodable files refused with the fix.
"""
from __future__ import annotations

import codecs

import pytest

from geomatics_toolbox.core.errors import FSI, PDI, InputError
from geomatics_toolbox.core.io import gcp as gcp_io
from geomatics_toolbox.core.io import text as text_io
from geomatics_toolbox.core.io.points import read_checkpoints_csv

CHECK = "id,x,y,z\n{a},500010.5,4000010.25,100.5\n{b},500020,4000030,101\n"
GCPS = ("id,col,row,x,y,role\n{a},10,20,500010.5,4000010.25,check\n"
        "{b},30,40,500020,4000030,check\nP3,50,10,500040,4000050,gcp\n"
        "P4,5,60,500005,4000060,gcp\nP5,70,70,500070,4000070,gcp\n")


def _both_readers(tmp_path, raw_check, raw_gcps):
    cp, g = tmp_path / "cp.csv", tmp_path / "gcps.csv"
    cp.write_bytes(raw_check)
    g.write_bytes(raw_gcps)
    ids, x, y, z = read_checkpoints_csv(cp)
    gcps = gcp_io.read_gcps(g, crs="EPSG:32632")
    assert x.tolist() == [500010.5, 500020.0] and z.tolist() == [100.5, 101.0]
    return ids, list(gcps.ids[:2])


@pytest.mark.parametrize("page,a,b", [
    ("cp1252", "Château-1", "Müller-Süd 2"),           # Western Excel "CSV"
    ("cp1256", "نقطة1", "چک 2"),                        # Arabic / Persian Windows
])
def test_check_points_and_gcps_read_one_legacy_file_alike(tmp_path, monkeypatch, page, a, b):
    """Was: the GCP reader fell back to cp1252, the check-point reader refused the file."""
    monkeypatch.setattr(text_io, "legacy_encoding", lambda: page)
    ids, gids = _both_readers(tmp_path, CHECK.format(a=a, b=b).encode(page),
                              GCPS.format(a=a, b=b).encode(page))
    assert ids == gids == [a, b]


@pytest.mark.parametrize("encoding", ["utf-8", "utf-8-sig", "utf-16"])
def test_unicode_files_read_alike_whatever_the_machine(tmp_path, monkeypatch, encoding):
    monkeypatch.setattr(text_io, "legacy_encoding", lambda: "cp1256")
    a, b = "Château-1", "نقطة چک ۲"
    raw_c, raw_g = (s.format(a=a, b=b).encode(encoding) for s in (CHECK, GCPS))
    if encoding == "utf-16":                                # Excel "Unicode Text": tabs
        raw_c, raw_g = (s.format(a=a, b=b).replace(",", "\t").encode("utf-16")
                        for s in (CHECK, GCPS))
        assert raw_c.startswith(codecs.BOM_UTF16_LE)
    assert _both_readers(tmp_path, raw_c, raw_g) == ([a, b], [a, b])


def test_default_legacy_page_is_the_machines_windows_code_page(monkeypatch):
    for system, page in (("cp1256", "cp1256"), ("cp1252", "cp1252"), ("UTF-8", "cp1252"),
                         ("ANSI_X3.4-1968", "cp1252"), ("", "cp1252"), ("cp932", "cp932"),
                         ("utf-8-sig", "cp1252"), ("no-such-codec", "cp1252")):
        monkeypatch.setattr(text_io.locale, "getencoding", lambda s=system: s, raising=False)
        assert text_io.legacy_encoding() == page, system


@pytest.mark.parametrize("raw,offset", [
    (b"id,x,y,z\nA,1,2,3\n\x00\x01\x02", 17),                # binary (NUL bytes)
    ("id,x,y,z\nA\x81,1,2,3\n".encode("latin-1"), 10),       # 0x81: undefined in 1252
])
def test_binary_or_undecodable_refused_by_both_readers_with_the_fix(tmp_path, monkeypatch,
                                                                   raw, offset):
    monkeypatch.setattr(text_io, "legacy_encoding", lambda: "cp1252")
    f = tmp_path / "bad.csv"
    f.write_bytes(raw)
    message = (rf"bad\.csv is not a text file in UTF-8 or cp1252 \(byte {offset} cannot be "
               r"read\): save it as text in UTF-8 \(in Excel: Save As, CSV UTF-8\)")
    with pytest.raises(InputError, match=message):
        read_checkpoints_csv(f)
    with pytest.raises(InputError, match=message) as info:
        gcp_io.read_gcps(f)
    ar = info.value.message("ar")
    assert ar.startswith(f"{FSI}{f}{PDI} ليس ملفاً نصياً بترميز UTF-8 أو {FSI}cp1252{PDI}")
    fa = info.value.message("fa")
    assert fa.startswith(f"{FSI}{f}{PDI} فایل متنی با رمزگذاری UTF-8 یا {FSI}cp1252{PDI} نیست")
