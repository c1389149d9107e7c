"""Deterministic synthetic test data (labelled ALS tiles, GCP sets and images).

Used by the tests, the benchmarks and ``make demo``; never shipped in the plugin zip
(``scripts/package.py`` excludes this folder).
"""
