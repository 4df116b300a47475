// Deliberately links soft-float helpers, for the test that the firmware nm check rejects them.
// Never add this pattern anywhere else: firmware and lib/ are integer-only.
int main() {
    volatile float f = 1.5f;
    f *= 2;
    return f > 2.5f ? 0 : 1;
}
