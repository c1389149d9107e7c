"""Photogrammetric planning: GSD and accuracy calculator, camera presets."""
