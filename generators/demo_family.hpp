#pragma once
// The closed-form demonstration family (see demo_family.cpp).
namespace brdftab::gen {
double demo_exp_cos_exact(double x, double y);
}
