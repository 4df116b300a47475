// Executes an undefined instruction, for the test that a crash reports itself through the
// fault/trap handler and ends the run (status 3) instead of hanging QEMU.
int main() {
    __builtin_trap();
}
