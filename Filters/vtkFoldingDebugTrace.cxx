#include "vtkFoldingDebugTrace.h"

#include <vtkObject.h>
#include <vtkOutputWindow.h>

#include <mutex>
#include <string>

namespace foldingmeshes
{
TraceSink DebugTrace(vtkObject* self)
{
  if (!self || !self->GetDebug())
    return TraceSink();
  // What vtkDebugMacro does, done here because vtkDebugMacro compiles to nothing in release
  // builds (NDEBUG), where DebugOn() should still show the algorithm's trace.
  return [self](const std::string& line)
  {
    static std::mutex mutex;
    const std::lock_guard<std::mutex> lock(mutex);
    if (!vtkObject::GetGlobalWarningDisplay())
      return;
    const std::string message = std::string(self->GetObjectDescription()) + ": " + line;
    vtkOutputWindowDisplayDebugText(__FILE__, __LINE__, message.c_str(), self);
  };
}
}
