#include <CppUTest/CommandLineTestRunner.h>
#include <CppUTest/MemoryLeakWarningPlugin.h>

// CppUTest's default new/delete overloads are not thread-safe: the frame
// decoder's worker threads (FileStereoCamera) allocating beside the test
// corrupted the leak detector's lists, a rare SIGSEGV or endless loop in
// test_recording. The thread-safe overloads keep the leak check.
int main(int argc, char** argv) {
  MemoryLeakWarningPlugin::turnOnThreadSafeNewDeleteOverloads();
  return CommandLineTestRunner::RunAllTests(argc, argv);
}
