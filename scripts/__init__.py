"""The Python scripts of the build, the release and the documentation (run as python -m scripts.NAME)."""
