"""Report rendering (HTML, SVG figures). Imports no domain sub-package."""
