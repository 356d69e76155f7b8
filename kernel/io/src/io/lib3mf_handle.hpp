#pragma once

#include <filesystem>
#include <memory>
#include <string>

#include <Model/COM/NMR_DLLInterfaces.h>

#include "nome/error.hpp"

namespace nome {

// lib3mf's handles are reference counted: each one we get is released once.
struct Lib3mfRelease {
  void operator()(NMR::PLib3MFBase* p) const { NMR::lib3mf_release(p); }
};
using Lib3mfHandle = std::unique_ptr<NMR::PLib3MFBase, Lib3mfRelease>;

// Throws IoError naming the file, the step and lib3mf's own message when a call failed.
inline void check_lib3mf(LIB3MFRESULT result, NMR::PLib3MFBase* owner, const std::filesystem::path& path,
                         const char* what) {
  using namespace NMR;
  if (result == LIB3MF_OK) return;
  std::string message;
  DWORD code = 0;
  LPCSTR text = nullptr;
  if (owner && lib3mf_getlasterror(owner, &code, &text) == LIB3MF_OK && text)
    message = std::string(": ") + text;
  throw IoError(path.string() + ": 3MF: " + what + " failed (lib3mf error " + std::to_string(result) + ")" +
                message);
}

}  // namespace nome
