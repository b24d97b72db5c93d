"""Each interface between generated C and Python, declared once (filled in below)."""
