"""Examples of using the FMUs: the CI check, the cross-check and FMI-LS-REF files, the Dask sweep."""
