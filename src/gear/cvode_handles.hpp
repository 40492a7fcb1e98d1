// The SUNDIALS objects of one CVODE integration, freed together. Private to the gear module.
#pragma once

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

namespace contensou::detail {

struct CvodeHandles {
  SUNContext ctx = nullptr;
  N_Vector y = nullptr, atol = nullptr, out = nullptr;
  SUNMatrix A = nullptr;
  SUNLinearSolver LS = nullptr;
  void* mem = nullptr;
  CvodeHandles() = default;
  CvodeHandles(const CvodeHandles&) = delete;
  CvodeHandles& operator=(const CvodeHandles&) = delete;
  ~CvodeHandles() {
    if (mem) CVodeFree(&mem);
    if (LS) SUNLinSolFree(LS);
    if (A) SUNMatDestroy(A);
    if (atol) N_VDestroy(atol);
    if (y) N_VDestroy(y);
    if (out) N_VDestroy(out);
    if (ctx) SUNContext_Free(&ctx);
  }
};

}  // namespace contensou::detail
