// Entry point of the test executable: runs one named case, all cases, or
// lists them. ctest runs one case per test (see CMakeLists.txt).
#include "afm_test_harness.h"

#include <cstdlib>
#include <exception>
#include <iostream>

std::string afm_test::shared_data_dir()
{
  if(const char* env = std::getenv("AFM_SHARED_DATA_DIR")) return env;
#ifdef AFM_SHARED_DATA_DIR
  return AFM_SHARED_DATA_DIR;
#else
  return "";
#endif
}

static bool run(const std::string& name, const std::function<void()>& f)
{
  try {
    f();
    std::cout << "PASS " << name << "\n";
    return true;
  } catch(const std::exception& e) {
    std::cout << "FAIL " << name << ": " << e.what() << "\n";
  } catch(...) {
    std::cout << "FAIL " << name << ": unknown exception\n";
  }
  return false;
}

int main(int argc, char* argv[])
{
  auto& reg = afm_test::registry();
  if(argc > 1 && std::string(argv[1]) == "--list") {
    for(const auto& t : reg) std::cout << t.first << "\n";
    return EXIT_SUCCESS;
  }
  int failed = 0, passed = 0;
  if(argc > 1) {
    for(int i = 1; i < argc; ++i) {
      auto it = reg.find(argv[i]);
      if(it == reg.end()) {
        std::cout << "FAIL " << argv[i] << ": no such test case\n";
        ++failed;
        continue;
      }
      run(it->first, it->second) ? ++passed : ++failed;
    }
  } else {
    for(const auto& t : reg) run(t.first, t.second) ? ++passed : ++failed;
  }
  std::cout << passed << " passed, " << failed << " failed\n";
  return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
