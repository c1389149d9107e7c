"""GCP image rectification: transformations, accuracy criteria, warping."""
