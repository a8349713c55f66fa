// mpmcut command-line program (being built: see issue 2).
int main() { return 0; }
