// Keeps every concept library non-empty while its sources are being written.
