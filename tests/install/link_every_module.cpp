// Links every echoplan module (tests/install/CMakeLists.txt); it has nothing to do.
int main() { return 0; }
