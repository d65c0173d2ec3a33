"""The elementary functions' accuracy against mpmath."""
