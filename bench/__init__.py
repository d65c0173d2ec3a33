"""The benchmark's Python: the fmpy overhead measurement and the frozen anchors' generator."""
