"""One decoding rule for the text files users make (GCP lists and check points).

UTF-16 with a BOM, a page the file names (``# encoding: cp1256``), UTF-8 with or without
a BOM, else the Windows code page whose reading of the names is text — the machine's own,
Windows-1256 (Arabic/Persian) or Windows-1252 (Western) —; binary, undecodable or
ambiguous files refused with the fix.
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
ARABIC = ("نقطة تحقق 1", "جسر الملك فهد")
#: Persian: ی and ک (and پ چ ژ گ, the zero-width non-joiner)
PERSIAN = ("ایستگاه یک", "نقطه\u200cی چک پل ژاله گ")
LATIN = ("Château-1", "Müller-Süd 2")
#: Windows-1256 has no Persian yeh (U+06CC): Windows writes the Arabic yeh (0xED)
CP1256_YEH = str.maketrans({"ی": "ي"})
MACHINES = [None, "cp1252", "cp1256"]          # Linux/macOS, Western and Arabic Windows


def _both_readers(tmp_path, raw_check, raw_gcps):
    cp, g = tmp_path / "cp.csv", tmp_path / "gcps.csv"
    cp.write_bytes(raw_check)
    g.write_bytes(raw_gcps)
    ids, x, y, z = read_checkpoints_csv(cp)
    gcps = gcp_io.read_gcps(g, crs="EPSG:32632")
    assert x.tolist() == [500010.5, 500020.0] and z.tolist() == [100.5, 101.0]
    return ids, list(gcps.ids[:2])


def _encode(names, encoding):
    a, b = names
    if encoding == "utf-16":                                # Excel "Unicode Text": tabs
        raw = [s.format(a=a, b=b).replace(",", "\t").encode("utf-16") for s in (CHECK, GCPS)]
        assert raw[0].startswith(codecs.BOM_UTF16_LE)
        return raw
    return [s.format(a=a, b=b).encode(encoding) for s in (CHECK, GCPS)]


@pytest.mark.parametrize("machine", MACHINES)
@pytest.mark.parametrize("names", [ARABIC, PERSIAN], ids=["arabic", "persian"])
def test_arabic_and_persian_names_in_cp1256_read_on_every_machine(tmp_path, monkeypatch,
                                                                  machine, names):
    """Was: on Linux/macOS (and Western Windows) a cp1256 file was read as cp1252:
    'نقطة تحقق 1' came out as 'äÞØÉ ÊÍÞÞ 1' (numbers right, names garbled)."""
    monkeypatch.setattr(text_io, "system_code_page", lambda: machine)
    names = tuple(n.translate(CP1256_YEH) for n in names)
    ids, gids = _both_readers(tmp_path, *_encode(names, "cp1256"))
    assert ids == gids == list(names)


@pytest.mark.parametrize("machine", MACHINES)
@pytest.mark.parametrize("encoding", ["utf-8", "utf-8-sig", "utf-16"])
@pytest.mark.parametrize("names", [ARABIC, PERSIAN, LATIN], ids=["arabic", "persian", "latin"])
def test_unicode_files_read_alike_whatever_the_machine(tmp_path, monkeypatch, machine,
                                                       encoding, names):
    monkeypatch.setattr(text_io, "system_code_page", lambda: machine)
    assert _both_readers(tmp_path, *_encode(names, encoding)) == (list(names), list(names))


@pytest.mark.parametrize("machine", MACHINES)
@pytest.mark.parametrize("names", [LATIN, ("École Ørsted", "Straße-Größe"),
                                   ("Peñón", "São-Þórshöfn"), ("Pointe-à-Pitre", "Nº7")])
def test_western_names_in_cp1252_still_read_on_every_machine(tmp_path, monkeypatch,
                                                             machine, names):
    """é/ü/â read the same in both pages; ß, Ø, É, ñ, º would read as Arabic in cp1256."""
    monkeypatch.setattr(text_io, "system_code_page", lambda: machine)
    ids, gids = _both_readers(tmp_path, *_encode(names, "cp1252"))
    assert ids == gids == list(names)


def test_mixed_latin_and_arabic_names_in_one_cp1256_file(tmp_path, monkeypatch):
    monkeypatch.setattr(text_io, "system_code_page", lambda: "cp1252")
    names = ("Château-1", "نقطة1")
    assert _both_readers(tmp_path, *_encode(names, "cp1256")) == (list(names), list(names))


@pytest.mark.parametrize("line", ["# encoding: cp1256", "# -*- coding: cp1256 -*-",
                                  "#coding=windows-1256"])
def test_a_declared_code_page_is_used(tmp_path, monkeypatch, line):
    """A first comment line naming the page decides (both readers skip '#' lines)."""
    monkeypatch.setattr(text_io, "system_code_page", lambda: None)
    a, b = "ب-1", "ج-2"         # one letter each: also È-1 / Ì-2 in cp1252
    raw = [(line + "\n" + s.format(a=a, b=b)).encode("cp1256") for s in (CHECK, GCPS)]
    assert _both_readers(tmp_path, *raw) == ([a, b], [a, b])


def test_a_utf8_byte_order_mark_wins_over_a_declared_page(tmp_path, monkeypatch):
    """A regression guard: this held before a836457 too (the declaration pattern did
    not match behind the BOM); decode_text now skips the declaration explicitly."""
    monkeypatch.setattr(text_io, "system_code_page", lambda: None)
    a, b = "ایستگاه یک", "Château-1"
    raw = [("# encoding: cp1256\n" + s.format(a=a, b=b)).encode("utf-8-sig")
           for s in (CHECK, GCPS)]
    assert _both_readers(tmp_path, *raw) == ([a, b], [a, b])


def test_ambiguous_names_refused_naming_the_file_and_the_fix(tmp_path, monkeypatch):
    """'ب-1' (cp1256) is 'È-1' in cp1252: both are text; no guess, a refusal."""
    monkeypatch.setattr(text_io, "system_code_page", lambda: None)
    f = tmp_path / "amb.csv"
    f.write_bytes(CHECK.format(a="ب-1", b="ج-2").encode("cp1256"))
    message = (r"amb\.csv is not saved in UTF-8 and its names read equally well in more "
               r"than one Windows code page \(cp1256, cp1252; for example ب-1 \| È-1\): "
               r"they would come out garbled\. Save it as text in UTF-8 \(in Excel: Save "
               r"As, CSV UTF-8\), or name its code page in a first line such as # "
               r"encoding: cp1256, and run again\.")
    with pytest.raises(InputError, match=message):
        read_checkpoints_csv(f)
    with pytest.raises(InputError, match=message) as info:
        gcp_io.read_gcps(f)
    ar, fa = info.value.message("ar"), info.value.message("fa")
    assert ar.startswith(f"{FSI}{f}{PDI} ") and "UTF-8" in ar and "# encoding: cp1256" in ar
    assert fa.startswith(f"{FSI}{f}{PDI} ") and "UTF-8" in fa and "# encoding: cp1256" in fa
    assert not any(w in ar + fa for w in ("saved", "garbled", "Windows code page"))
    # on an Arabic Windows machine its own page breaks the tie
    monkeypatch.setattr(text_io, "system_code_page", lambda: "cp1256")
    assert read_checkpoints_csv(f)[0] == ["ب-1", "ج-2"]


def test_machine_code_page_is_the_windows_ansi_page_or_none(monkeypatch):
    for system, page in (("cp1256", "cp1256"), ("cp1252", "cp1252"), ("UTF-8", None),
                         ("ANSI_X3.4-1968", None), ("", None), ("cp932", "cp932"),
                         ("utf-8-sig", None), ("no-such-codec", None)):
        monkeypatch.setattr(text_io.locale, "getencoding", lambda s=system: s, raising=False)
        assert text_io.system_code_page() == page, system


@pytest.mark.parametrize("raw,offset,pages", [
    (b"id,x,y,z\nA,1,2,3\n\x00\x01\x02", 17, "cp1256/cp1252"),      # binary (NUL bytes)
    ("# encoding: cp1252\nid,x,y,z\nA\x81,1,2,3\n".encode("latin-1"), 29,
     "cp1252"),                                  # 0x81: undefined in the named page
])
def test_binary_or_undecodable_refused_by_both_readers_with_the_fix(tmp_path, monkeypatch,
                                                                   raw, offset, pages):
    monkeypatch.setattr(text_io, "system_code_page", lambda: None)
    f = tmp_path / "bad.csv"
    f.write_bytes(raw)
    message = (rf"bad\.csv is not a text file in UTF-8 or {pages} \(byte {offset} cannot be "
               r"read\): save it as text in UTF-8 \(in Excel: Save As, CSV UTF-8\)")
    with pytest.raises(InputError, match=message):
        read_checkpoints_csv(f)
    with pytest.raises(InputError, match=message) as info:
        gcp_io.read_gcps(f)
    ar = info.value.message("ar")
    assert ar.startswith(f"{FSI}{f}{PDI} ليس ملفاً نصياً بترميز UTF-8 أو {FSI}{pages}{PDI}")
    fa = info.value.message("fa")
    assert fa.startswith(f"{FSI}{f}{PDI} فایل متنی با رمزگذاری UTF-8 یا {FSI}{pages}{PDI} نیست")
