#include "cli/wgsl_executor.h"

#ifdef WG_HAVE_RUNTIME
#include "cli/wgsl_checks.h"
#include "runtime/runtime_error.h"

namespace wg {

std::unique_ptr<accuracy::GpuExecutor> wgslExecutorOrWhyNot(const std::string& notRun,
                                                           std::initializer_list<const char*> packages) {
  for (const char* package : packages)
    if (std::string why = webgpuClientMissing(package); !why.empty())
      throw rt::RuntimeError(rt::RuntimeError::Kind::Environment, notRun + why);
  try {
    return accuracy::makeWgslExecutor({nodeExecutable(), webgpuClientDir()});
  } catch (const rt::RuntimeError& e) {
    if (e.kind() != rt::RuntimeError::Kind::Environment) throw;
    throw rt::RuntimeError(rt::RuntimeError::Kind::Environment, notRun + e.what());
  }
}

}  // namespace wg
#endif
