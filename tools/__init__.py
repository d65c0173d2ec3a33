"""Tools beside the FMUs: the FMU packer, the macOS binaries' static check, the elementary functions' accuracy."""
