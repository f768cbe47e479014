"""String art from a photo: a target image, the board's nail-pair lines, a greedy choice.

Pure numpy (Pillow to read images; SSIM is our own, in quality.py): no Qt, so the
same code runs in the station's worker thread and on the command line.
"""
