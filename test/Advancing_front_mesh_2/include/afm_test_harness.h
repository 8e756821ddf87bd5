// Minimal test registry for the Advancing_front_mesh_2 test suite.
//
// Every test file defines cases with AFM_TEST_CASE(name) { ... } and checks
// with AFM_CHECK(cond) / AFM_CHECK_MSG(cond, msg). One executable holds all
// cases; CMake registers each case with ctest by scanning the sources for
// AFM_TEST_CASE, and runs it as `test_advancing_front_mesh_2 NAME`.
// Keeping one executable (a few translation units) keeps CGAL's compile time
// within the CI budget.

#ifndef AFM_TEST_HARNESS_H
#define AFM_TEST_HARNESS_H

#include <functional>
#include <iostream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>

namespace afm_test {

struct Failure : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

inline std::map<std::string, std::function<void()> >& registry()
{
  static std::map<std::string, std::function<void()> > r;
  return r;
}

struct Registrar
{
  Registrar(const char* name, void (*f)()) { registry()[name] = f; }
};

// Directory of ../shared/data, or empty when it is not beside the checkout.
// Set by CMake at configure time (AFM_SHARED_DATA_DIR) and overridable with
// the environment variable of the same name.
std::string shared_data_dir();

} // namespace afm_test

#define AFM_TEST_CASE(name)                                                  \
  static void name();                                                        \
  static ::afm_test::Registrar name##_registrar(#name, &name);               \
  static void name()

#define AFM_CHECK_MSG(cond, msg)                                             \
  do {                                                                       \
    if(!(cond)) {                                                            \
      std::ostringstream afm_os_;                                            \
      afm_os_ << __FILE__ << ":" << __LINE__ << ": check failed: " #cond    \
              << " -- " << msg;                                              \
      throw ::afm_test::Failure(afm_os_.str());                              \
    }                                                                        \
  } while(false)

#define AFM_CHECK(cond) AFM_CHECK_MSG(cond, "")

#endif // AFM_TEST_HARNESS_H
