// The program that precompiles GoogleTest and fmt for every test program (tests/CMakeLists.txt,
// TRAPDEM_TEST_PCH). It tests nothing and is not run: the header is what it is built for.
int main() { return 0; }
