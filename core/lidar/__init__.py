"""LiDAR point-cloud processing: ground filters, low-noise flags, filter accuracy."""
