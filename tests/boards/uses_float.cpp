// Deliberately bad firmware: one float multiply. The forbidden-symbol checker
// must reject the linked image (tests/boards/expect_checker_rejects.cmake).
volatile int input = 3;
volatile int output;
extern "C" void Reset_Handler() {
  output = static_cast<int>(static_cast<float>(input) * 1.5f);
  for (;;) {
  }
}
