"""Point lists: positions to visit, one per line (the plainest job an XY stage runs)."""
