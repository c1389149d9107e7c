"""Terrain models: grids, IDW, kriging, DSM/nDSM and DTM accuracy."""
