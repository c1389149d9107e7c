"""Input/output: LAS/LAZ, rasters, GCP files, point tables, and the output contract.

The only place in ``core`` that touches files. Imports no domain sub-package.
"""
