package tracer

import scala.annotation.tailrec

/** Helpers for steps that may fail with an error value (`Either[E, _]`). */
object Eithers:

  /** `f` applied to each item in order: every result, or the first error (no later item is tried). */
  def traverse[E, A, B](items: List[A])(f: A => Either[E, B]): Either[E, List[B]] =
    @tailrec
    def loop(rest: List[A], done: List[B]): Either[E, List[B]] = rest match
      case Nil          => Right(done.reverse)
      case item :: more =>
        f(item) match
          case Right(b)    => loop(more, b :: done)
          case Left(error) => Left(error)
    loop(items, Nil)
