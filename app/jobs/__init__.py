"""Jobs: files turned into machine-independent programs, previewed and run."""
