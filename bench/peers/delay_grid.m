% bench/peers/delay_grid.m -- the peers of issue 48's long-delay targets, in Octave: what a user who
% wants a few digits writes instead of hapstab's certified paths. Vectorised double grids on
% theta in (0, pi]; each prints its value and its CPU time per evaluation (cputime, the mean of
% `reps` runs after one warm-up), so that bench/peers/README.md compares them with hapstab's CPU
% time on the same case.
%
%   octave --no-gui -q --eval "addpath('bench/peers'); delay_grid('bstar', 1e6, 1e4, 5)"
%   octave --no-gui -q --eval "addpath('bench/peers'); delay_grid('kmax', 1e4, 1000, 50)"
%
% bstar: b* of paper 001 (45) with a delay of n samples on the resonant H of bench/delay.cpp,
%   H = (z - 1)/(z^2 - 2 r (3/10) z + r^2), r = 1 - 1e-5, T = 1/1000:
%   f(theta) = (T/2) (Re w - Im w cot(theta/2)),  w = H(e^{j theta}) e^{-j n theta};  b* = max f.
% kmax: sup K of the one-DOF loop of bench/delay.cpp (device 1/(s^2 + s) behind a zero-order hold,
%   wall K + B (z - 1)/(T z), B = 1/2, T = 1/1000, n samples of delay) by the D-decomposition on the
%   grid: K(theta) = -(z^n / G(z) + B (z - 1)/(T z)), the crossings where Im K changes sign
%   (linear interpolation), the least positive Re K; G(z) = ((T - 1 + e^-T) z + 1 - e^-T - T e^-T)
%   / ((z - 1)(z - e^-T)), the ZOH of 1/(s (s + 1)).
function delay_grid(what, N, n, reps)
  T = 1/1000;
  switch what
    case 'bstar'
      r = 1 - 1e-5;
      num = [1 -1]; den = [1, -2*r*0.3, r^2];
      f = @() bstar(num, den, T, N, n);
    case 'kmax'
      f = @() kmax(T, 0.5, N, n);
    otherwise
      error('delay_grid: what must be bstar or kmax');
  end
  v = f();  % warm-up
  t0 = cputime;
  for i = 1:reps
    v = f();
  end
  t = (cputime - t0) / reps;
  printf('%s N=%d n=%d value=%.17g cpu_seconds=%.6g\n', what, N, n, v, t);
end

function b = bstar(num, den, T, N, n)
  th = pi * (1:N-1) / (N-1);
  z = exp(1j * th);
  w = polyval(num, z) ./ polyval(den, z) .* exp(-1j * n * th);
  b = max(T / 2 * (real(w) - imag(w) .* cot(th / 2)));
end

function K = kmax(T, B, N, n)
  e = exp(-T);
  th = pi * (1:N) / N;
  z = exp(1j * th);
  G = ((T - 1 + e) * z + (1 - e - T * e)) ./ ((z - 1) .* (z - e));
  k = -(z .^ n ./ G + B * (z - 1) ./ (T * z));
  s = find(sign(imag(k(1:end-1))) ~= sign(imag(k(2:end))));
  a = imag(k(s)) ./ (imag(k(s)) - imag(k(s+1)));
  c = real(k(s)) + a .* (real(k(s+1)) - real(k(s)));
  c = c(c > 0 & isfinite(c));
  K = min([c, Inf]);
end
