"""The SSP systems of the FMUs and their connection graph."""
